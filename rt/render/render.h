// Renders an image, in parallel over rows. Chapter 01.
// Each pixel averages samples_per_pixel estimates of the radiance along camera rays; the result
// depends only on the scene, the settings and the seed, never on the number of threads (see
// sampler.h). A render may be one part of a bigger one: a window of the image (crop) and a range
// of each pixel's sample indices (samples). Since a pixel sample depends only on (pixel, sample
// index, seed), the parts of a split render hold exactly the numbers of the whole one, and
// tools/merge puts them back together.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "rt/camera/camera.h"
#include "rt/image/image.h"
#include "rt/integrators/estimator.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"

namespace rt {

// A window of the image in pixels from the top-left: columns x0 <= x < x1, rows y0 <= y < y1.
struct pixel_window {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    static pixel_window whole(const film& f) { return {0, 0, f.width, f.height}; }
};

// A range of each pixel's sample indices: from <= k < to.
struct sample_range {
    int from = 0, to = 0;

    int count() const { return to - from; }
};

// [ch17 begin]
// Whether a pixel has samples enough before its last (chapter 17's adaptive sampling,
// rt/render/adaptive_sampling.h). Asked after first_check() samples and at every doubling of
// that count, with the pixel's running mean and sum of squared deviations m2 per channel over
// its n samples: its own samples only, so that the image never depends on the threads.
class stopping_rule {
  public:
    virtual ~stopping_rule()                                                         = default;
    virtual int first_check() const                                                  = 0;
    virtual bool enough(const double (&mean)[3], const double (&m2)[3], int n) const = 0;
};
// [ch17 end]

// How to render: a scene brings its own defaults (its report settings); flags override them.
struct render_settings {
    int width             = 400;  // Image width in pixels; the height from the aspect ratio
    int samples_per_pixel = 100;  // Camera samples per pixel of the whole render
    int max_depth         = 50;   // Ray segments followed per path at most
    std::uint64_t seed    = 1;    // Selects the random streams
    int threads           = 0;    // 0 = all cores
    // One part of a split render (none: the whole image, every sample index).
    std::optional<pixel_window> crop;     // Render only this window; the image is its size
    std::optional<sample_range> samples;  // Only these sample indices; to <= samples_per_pixel
    // Where pixel samples take their numbers: chapter 01's independent PCG32 streams, unless
    // a program chooses another (chapter 16's Sobol' points).
    sampler_factory make_sampler = independent_sampler::make;
    // When a pixel may stop before samples_per_pixel (none: never). Not with `samples`: the
    // parts of a split render could not know where the whole one would have stopped.
    std::shared_ptr<const stopping_rule> stop_early;  // [ch17]
};

// Everything a chapter's program renders: how the camera looks, how a sample is estimated, and
// the scene's own default settings.
struct render_job {
    std::shared_ptr<camera> cam = std::make_shared<camera>();
    std::shared_ptr<const radiance_estimator> estimator;
    render_settings settings;
};

struct render_result {
    image mean;              // the estimate: the average of the samples per pixel
    image mean_variance;     // its variance per channel: sample variance / samples averaged
    double seconds = 0;      // wall-clock time of the render loop
    pixel_window window;     // the pixels rendered (the whole film without a crop)
    sample_range samples;    // the sample indices rendered per pixel
    std::uint64_t rays = 0;  // rays the estimator traced into the world (ray_count.h)
    int threads        = 0;  // worker threads used
    // Camera samples estimated: the window's pixels times the sample range, fewer where a
    // pixel stopped early (render_settings::stop_early).
    std::uint64_t camera_samples = 0;
};

// The window and sample range a render of f with these settings covers. Throws user_error if
// the crop is empty or not inside f, or the range is empty or not inside
// [0, samples_per_pixel).
pixel_window window_of(const film& f, const render_settings& settings);
sample_range samples_of(const render_settings& settings);

// Told of every row of the window once it is done, by whichever thread finished it, so an
// implementation must be thread-safe; the render loop never waits for it to return quickly.
// (The program's progress line, rt/program/progress.h, is one.)
class row_observer {
  public:
    virtual void row_done() = 0;

  protected:
    ~row_observer() = default;
};

// cam must have been initialized for f. Throws user_error for a bad crop or sample range.
// rows, if given, hears of each finished row.
render_result render(const film& f, const camera& cam, const radiance_estimator& estimator,
                     const render_settings& settings, row_observer* rows = nullptr);

}  // namespace rt
