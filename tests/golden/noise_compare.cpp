// noise_compare TEST.pfm TEST_VARIANCE.pfm TEST_SPP REF.pfm REF_VARIANCE.pfm REF_SPP
// Exit 0 when the test render agrees with the converged reference within its noise (see
// tests/noise_statistic.h for the statistic), 1 when it does not, 2 on bad input.
#include <cstdio>
#include <exception>
#include <string>

#include "noise_statistic.h"
#include "rt/image/image_io.h"

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr,
                     "usage: noise_compare TEST.pfm TEST_VAR.pfm TEST_SPP REF.pfm REF_VAR.pfm "
                     "REF_SPP\n");
        return 2;
    }
    try {
        rt::image test = rt::read_pfm(argv[1]), test_var = rt::read_pfm(argv[2]);
        rt::image ref = rt::read_pfm(argv[4]), ref_var = rt::read_pfm(argv[5]);
        double test_spp = std::stod(argv[3]), ref_spp = std::stod(argv[6]);
        if (!(test_spp >= 1 && ref_spp >= 1)) {
            std::fprintf(stderr, "noise_compare: sample counts must be >= 1\n");
            return 2;
        }
        for (const rt::image* img : {&test_var, &ref, &ref_var}) {
            if (img->width() != test.width() || img->height() != test.height()) {
                std::fprintf(stderr, "noise_compare: image sizes differ\n");
                return 2;
            }
        }
        auto r = rt_test::compare_within_noise(test, test_var, ref, ref_var, ref_spp / test_spp);
        std::printf(
            "noise_compare: %d of %d block tests beyond |z| = %.2f; worst z = %.2f at "
            "block (%d, %d) channel %d\n",
            r.failed, r.blocks, r.z_limit, r.worst_z, r.worst_x, r.worst_y, r.worst_channel);
        return r.passed() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "noise_compare: error: %s\n", e.what());
        return 2;
    }
}
