// Chapter 06's scenes (chapters/ch06_defocus/lens_scenes.h): the lens of book 1's final scene.
// The book gives its blur as a defocus angle, 0.6 degrees: the apex angle of the cone from a
// point of the focus plane to the lens disk. Our camera takes the lens diameter instead, so the
// scene converts: aperture = 2 focus_dist tan(0.3 degrees). The golden image renders only the
// glass scene, so the final scene's lens is checked here, as the angle it must subtend.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <optional>

#include "ch06_defocus/lens_scenes.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/scalar.h"

using rt::real;

namespace {

// The scene's camera as the thin lens it must be.
std::shared_ptr<rt::thin_lens_camera> lens_of(const rt::scene& sc) {
    auto cam = std::dynamic_pointer_cast<rt::thin_lens_camera>(sc.cam);
    REQUIRE(cam != nullptr);
    return cam;
}

// The defocus angle in degrees: the full angle the lens disk subtends from the focus plane.
real defocus_angle_degrees(const rt::thin_lens_camera& cam) {
    return 2 * std::atan(cam.aperture / 2 / cam.focus_dist) * 180 / rt::pi;
}

}  // namespace

TEST_CASE("lens scenes: book 1's final scene has the book's defocus angle, 0.6 degrees",
          "[camera][ch06]") {
    // At focus distance 10 that is a lens 0.1047 wide. An angle taken in degrees where tan()
    // wants radians would make it 6.19 wide (a defocus angle of 34 degrees); one in radians
    // converted twice, 0.0018 wide.
    const auto cam = lens_of(book1_final_scene(std::nullopt, std::nullopt));
    CAPTURE(cam->aperture, cam->focus_dist);
    CHECK(cam->focus_dist == 10);
    INFO("the lens subtends " << defocus_angle_degrees(*cam)
                              << " degrees from the focus plane; the book's angle is 0.6");
    CHECK(defocus_angle_degrees(*cam) == Approx(0.6).epsilon(1e-4));
}

TEST_CASE("lens scenes: in the final scene, a focus distance given alone keeps the 0.6 degrees",
          "[camera][ch06]") {
    // --focus-dist without --aperture: the lens follows the focus distance, so the blur of a
    // point at a given fraction of the focus distance stays the book's.
    for (real focus : {real(2.5), real(5), real(40)}) {
        const auto cam = lens_of(book1_final_scene(std::nullopt, focus));
        CAPTURE(focus, cam->aperture);
        CHECK(cam->focus_dist == focus);
        CHECK(defocus_angle_degrees(*cam) == Approx(0.6).epsilon(1e-4));
    }
    // --aperture given: taken as it is.
    const auto given = lens_of(book1_final_scene(real(0.25), std::nullopt));
    CHECK(given->aperture == real(0.25));
}

TEST_CASE("lens scenes: the glass scene is seen through the book's 20-degree field of view",
          "[camera][ch06]") {
    // The camera takes its vertical field of view in degrees and converts it once; a scene that
    // converts it too hands the camera 0.35 "degrees", a close-up of a tiny patch.
    const auto cam = lens_of(glass_scene_through_lens(std::nullopt, std::nullopt));
    INFO("the glass scene's camera has vfov " << cam->vfov << " (degrees); the book's is 20");
    CHECK(cam->vfov == Approx(20));
}
