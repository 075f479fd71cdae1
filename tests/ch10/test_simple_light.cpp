// Chapter 10's scene (chapters/ch10_lights/simple_light.h): lit by its two lights alone. A ray
// that leaves the scene must see black, or the sky lights the marble and the lamps barely show:
// the daylight of chapters 01-09 left on in a scene meant to be seen in the dark.
#include <catch2/catch.hpp>

#include "ch10_lights/simple_light.h"
#include "rt/core/vec3.h"

using rt::vec3;

TEST_CASE("simple light: a ray that escapes the lit scene sees black, not chapter 01's sky",
          "[ch10]") {
    const rt::scene scene = simple_light();
    for (const vec3& d : {vec3(0, 1, 0), vec3(0, -1, 0), vec3(1, 0.2, -0.3), vec3(-0.4, 0.7, 1)}) {
        const rt::color sky = scene.sky.radiance(d);
        CAPTURE(d, sky);
        INFO("the background must be black: the scene is lit by its lights alone");
        CHECK(sky.x() == 0);
        CHECK(sky.y() == 0);
        CHECK(sky.z() == 0);
    }
}
