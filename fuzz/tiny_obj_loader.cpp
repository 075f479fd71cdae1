// Debian's tinyobjloader (package libtinyobjloader-dev), its double-precision build compiled into
// the OBJ fuzz target with the sanitizers, so that a fault inside it shows where it happens (the
// normal build links Debian's prebuilt libtinyobjloader_double.so, the same source).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
