#include "rt/program/run_stats.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "rt/core/error.h"
#include "rt/core/scalar.h"

namespace rt {

namespace fs = std::filesystem;

namespace {

// A JSON string: quotes, backslashes and control characters escaped; other bytes as they are
// (UTF-8 in, UTF-8 out).
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

// The shortest text that reads back as the same double. JSON has no infinity: a rate over a
// time too short to measure is given over one nanosecond (per_second).
std::string number(double x) {
    char text[32];
    auto [end, ec] = std::to_chars(text, text + sizeof text, x);
    return ec == std::errc() ? std::string(text, end) : "0";
}

double per_second(double count, double seconds) {
    return count / std::max(seconds, 1e-9);
}

std::string relative(const std::string& path, const std::string& folder) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    fs::path base     = fs::absolute(folder, ec);
    if (ec) return path;
    return absolute.lexically_proximate(base).string();
}

}  // namespace

std::string to_json(const run_stats& s, const std::string& relative_to) {
    const render_settings& set = s.settings;
    const auto samples         = double(s.camera_samples);
    std::ostringstream j;
    j << "{\n";
    j << "  \"program\": " << quoted(s.program) << ",\n";
    j << "  \"integrator\": " << quoted(s.integrator) << ",\n";
    j << "  \"sampler\": " << quoted(s.sampler) << ",\n";
    j << "  \"scalar\": " << quoted(sizeof(real) == sizeof(float) ? "float" : "double") << ",\n";
    j << "  \"options\": {";
    for (std::size_t i = 0; i < s.options.size(); ++i)
        j << (i ? ", " : "") << quoted(s.options[i].first) << ": " << quoted(s.options[i].second);
    j << "},\n";
    j << "  \"settings\": {\n";
    j << "    \"width\": " << s.full.width << ",\n";
    j << "    \"height\": " << s.full.height << ",\n";
    j << "    \"spp\": " << set.samples_per_pixel << ",\n";
    j << "    \"max_depth\": " << set.max_depth << ",\n";
    j << "    \"seed\": " << set.seed << ",\n";
    j << "    \"threads\": " << set.threads << ",\n";
    j << "    \"crop\": [" << s.window.x0 << ", " << s.window.y0 << ", " << s.window.x1 << ", "
      << s.window.y1 << "],\n";
    j << "    \"samples\": [" << s.samples.from << ", " << s.samples.to << "]\n";
    j << "  },\n";
    j << "  \"camera_samples\": " << std::uint64_t(samples) << ",\n";
    j << "  \"rays\": " << s.rays << ",\n";
    j << "  \"seconds\": " << number(s.seconds) << ",\n";
    j << "  \"process_seconds\": " << number(s.process_seconds) << ",\n";
    j << "  \"samples_per_second\": " << number(per_second(samples, s.seconds)) << ",\n";
    j << "  \"rays_per_second\": " << number(per_second(double(s.rays), s.seconds)) << ",\n";
    j << "  \"outputs\": [";
    for (std::size_t i = 0; i < s.outputs.size(); ++i)
        j << (i ? ", " : "") << quoted(relative(s.outputs[i], relative_to));
    j << "],\n";
    j << "  \"variance_out\": "
      << (s.variance_output.empty() ? "null" : quoted(relative(s.variance_output, relative_to)))
      << ",\n";
    j << "  \"command\": [";
    for (std::size_t i = 0; i < s.command.size(); ++i) j << (i ? ", " : "") << quoted(s.command[i]);
    j << "]\n";
    j << "}\n";
    return j.str();
}

std::string stats_path_problem(const std::string& path) {
    if (fs::path(path).extension() != ".json") return "stats file '" + path + "' must end in .json";
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return "stats file '" + path + "': folder '" + folder.string() + "' does not exist";
    if (fs::is_directory(path, ec)) return "stats file '" + path + "' is a folder";
    return "";
}

void write_stats(output_set& outputs, const std::string& path, const run_stats& stats) {
    if (auto problem = stats_path_problem(path); !problem.empty()) throw user_error(problem);
    fs::path folder  = fs::path(path).parent_path();
    std::string text = to_json(stats, folder.empty() ? "." : folder.string());
    outputs.add(path, [&](temporary_file& file) { file.append(text.data(), text.size()); });
}

}  // namespace rt
