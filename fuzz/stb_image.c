/* Debian's stb_image.h and stb_image_write.h (package libstb-dev), compiled into the fuzz targets
   with the sanitizers and libFuzzer's coverage, so that a fault inside the decoder is seen where
   it happens. The normal build links Debian's prebuilt libstb.so instead; this is the same
   packaged source, not a copy. */
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
