#include "rt/scene_files/scene_words.h"

#include <charconv>

namespace rt {

std::vector<std::string_view> fresnel_names() {
    return {"schlick", "exact", "book-schlick"};
}

std::optional<fresnel_model> fresnel_named(std::string_view name) {
    if (name == "schlick") return fresnel_model::schlick;
    if (name == "exact") return fresnel_model::exact;
    if (name == "book-schlick") return fresnel_model::book_schlick;
    return std::nullopt;
}

std::string_view fresnel_name(fresnel_model model) {
    switch (model) {
        case fresnel_model::exact:
            return "exact";
        case fresnel_model::book_schlick:
            return "book-schlick";
        case fresnel_model::schlick:
            break;
    }
    return "schlick";
}

std::optional<double> aspect_ratio_named(const std::string& text) {
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) return std::nullopt;
    auto whole = [&](std::size_t from, std::size_t to) -> std::optional<int> {
        int n             = 0;
        const char* a     = text.data() + from;
        const char* b     = text.data() + to;
        auto [end, error] = std::from_chars(a, b, n);
        if (a == b || error != std::errc() || end != b || n < 1 || n > 100000) return std::nullopt;
        return n;
    };
    const auto w = whole(0, colon), h = whole(colon + 1, text.size());
    if (!w || !h) return std::nullopt;
    return double(*w) / double(*h);
}

std::optional<std::string> aspect_ratio_name(double ratio) {
    for (int h = 1; h <= 64; ++h)
        for (int w = 1; w <= 64; ++w)
            if (double(w) / double(h) == ratio) return std::to_string(w) + ":" + std::to_string(h);
    return std::nullopt;
}

}  // namespace rt
