// Chapter 01's whole renderer: with nothing in the scene to hit, every ray sees the background.
#pragma once

#include "rt/integrators/estimator.h"
#include "rt/scene/background.h"

namespace rt {

class sky_only : public radiance_estimator {
  public:
    explicit sky_only(const background& b) : sky(b) {}
    color radiance(const ray& r, sampler&, int) const override {
        return sky.radiance(r.direction());
    }
    std::string_view name() const override { return "sky"; }

  private:
    background sky;
};

}  // namespace rt
