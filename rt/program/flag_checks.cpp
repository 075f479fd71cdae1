#include "rt/program/flag_checks.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "rt/files/image_outputs.h"
#include "rt/program/run_stats.h"

namespace rt {

namespace {

// Exactly `count` decimal integers separated by `separator`, and nothing else: "0,0,20,10" for
// four and ','; not "0,0,20", "0,0,20,10," or " 0,0,20,10".
bool parse_integers(const std::string& text, char separator, int count, int* out) {
    const char* p   = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < count; ++i) {
        if (i > 0) {
            if (p == end || *p != separator) return false;
            ++p;
        }
        auto [next, ec] = std::from_chars(p, end, out[i]);
        if (ec != std::errc() || next == p) return false;
        p = next;
    }
    return p == end;
}

// "must be a finite number <relation> <lo>" unless the whole text is a finite number that
// satisfies it.
CLI::Validator finite_number(double lo, bool lo_allowed) {
    std::ostringstream rule;
    rule << "must be a finite number " << (lo_allowed ? ">= " : "> ") << lo;
    return CLI::Validator(
        [lo, lo_allowed, rule = rule.str()](std::string& text) -> std::string {
            double value   = 0;
            auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            const bool ok  = ec == std::errc() && end == text.data() + text.size() &&
                            std::isfinite(value) && (value > lo || (lo_allowed && value == lo));
            return ok ? "" : rule + ", got " + text;
        },
        rule.str().substr(8));  // the help shows "FLOAT:a finite number >= 0"
}

}  // namespace

CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
            std::uint64_t value = 0;
            auto [end, ec]      = std::from_chars(text.data(), text.data() + text.size(), value);
            if (ec == std::errc() && end == text.data() + text.size() && value >= lo && value <= hi)
                return "";
            return "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                   ", got " + text;
        },
        // The help shows "INT:INT in [1, 16384]"; a bound of 2^64 - 1 (--seed) says nothing.
        hi == UINT64_MAX ? "" : "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

CLI::Validator number_at_least(double lo) {
    return finite_number(lo, true);
}
CLI::Validator number_above(double lo) {
    return finite_number(lo, false);
}

CLI::Validator output_file(const std::vector<std::string>& extensions) {
    return CLI::Validator(
        [extensions](std::string& path) -> std::string {
            std::string problem = output_path_problem(path);
            if (!problem.empty()) return problem;
            for (const auto& ext : extensions)
                if (path.size() >= ext.size() && path.ends_with(ext)) return "";
            std::string names;
            for (std::size_t k = 0; k < extensions.size(); ++k)
                names += (k == 0 ? "" : k + 1 == extensions.size() ? " or " : ", ") + extensions[k];
            return "output '" + path + "' must end in " + names;
        },
        "FILE");
}

CLI::Validator stats_file() {
    return CLI::Validator([](std::string& path) { return stats_path_problem(path); }, "FILE");
}

std::optional<pixel_window> parse_crop(const std::string& text) {
    int v[4];
    if (!parse_integers(text, ',', 4, v)) return std::nullopt;
    return pixel_window{v[0], v[1], v[2], v[3]};
}

std::optional<sample_range> parse_samples(const std::string& text) {
    int v[2];
    if (!parse_integers(text, ':', 2, v)) return std::nullopt;
    return sample_range{v[0], v[1]};
}

CLI::Validator crop_syntax() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            return parse_crop(text) ? "" : "crop must be X0,Y0,X1,Y1 (integers), got " + text;
        },
        "X0,Y0,X1,Y1");
}

CLI::Validator samples_syntax() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            return parse_samples(text) ? ""
                                       : "sample range must be FROM:TO (integers), got " + text;
        },
        "FROM:TO");
}

}  // namespace rt
