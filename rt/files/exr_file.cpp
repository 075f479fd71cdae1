#include "rt/files/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <half.h>
#include <openexr.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <exception>
#include <vector>

#include "rt/core/error.h"

namespace rt {

namespace {

// The library's output stream, into memory: it seeks back to write the table of line offsets
// last, which a byte sink cannot do.
class memory_stream final : public Imf::OStream {
  public:
    memory_stream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        const auto end = std::size_t(position) + std::size_t(n);
        if (end > bytes.size()) bytes.resize(end);
        std::memcpy(bytes.data() + position, c, std::size_t(n));
        position = end;
    }
    std::uint64_t tellp() override { return position; }
    void seekp(std::uint64_t pos) override { position = pos; }

    std::vector<char> bytes;

  private:
    std::uint64_t position = 0;
};

constexpr std::array<const char*, 3> channel_names = {"R", "G", "B"};

}  // namespace

void encode_exr(const image& img, exr_pixels pixels, const byte_sink& sink) {
    const int w = img.width(), h = img.height();
    const Imf::PixelType type = pixels == exr_pixels::float32 ? Imf::FLOAT : Imf::HALF;
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : channel_names) header.channels().insert(name, Imf::Channel(type));

    // Interleaved R, G, B as the image holds them; halves in a copy of the same layout.
    std::vector<half> halves;
    const char* base        = reinterpret_cast<const char*>(img.data().data());
    std::size_t sample_size = sizeof(float);
    if (pixels == exr_pixels::half16) {
        halves.reserve(img.data().size());
        for (const float v : img.data())
            halves.emplace_back(std::clamp(v, -largest_half, largest_half));
        base        = reinterpret_cast<const char*>(halves.data());
        sample_size = sizeof(half);
    }
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < channel_names.size(); ++c)
        frame.insert(channel_names[c],
                     Imf::Slice(type, const_cast<char*>(base + c * sample_size), 3 * sample_size,
                                3 * sample_size * std::size_t(w)));
    memory_stream out;
    try {
        // The file is complete once it is closed (its line offsets are written then).
        Imf::OutputFile file(out, header);
        file.setFrameBuffer(frame);
        file.writePixels(h);
    } catch (const std::exception& e) {
        throw user_error(std::string("the OpenEXR library could not write the image: ") + e.what());
    }
    sink(out.bytes.data(), out.bytes.size());
}

namespace {

// What the core library says of a failure (it would print it on stderr otherwise).
struct read_state {
    const char* data = nullptr;  // the file's bytes, when read from memory
    std::size_t size = 0;
    std::string message;
};

void keep_message(exr_const_context_t context, exr_result_t, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user && message)
        static_cast<read_state*>(user)->message = message;
}

int64_t read_memory(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                    exr_stream_error_func_ptr_t) {
    const auto* state = static_cast<const read_state*>(user);
    if (offset >= state->size) return 0;
    const auto n = std::min<std::uint64_t>(size, state->size - offset);
    std::memcpy(buffer, state->data + offset, n);
    return int64_t(n);
}

int64_t size_of_memory(exr_const_context_t, void* user) {
    return int64_t(static_cast<const read_state*>(user)->size);
}

// Closes the context whichever way the read ends.
struct context_guard {
    exr_context_t context         = nullptr;
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    bool decoding                 = false;
    ~context_guard() {
        if (decoding) exr_decoding_destroy(context, &decoder);
        if (context) exr_finish(&context);
    }
};

exr_image read_exr_with(const std::string& name, read_state& state, bool from_memory,
                        long long max_pixels) {
    auto refuse = [&](const std::string& why) -> user_error {
        return user_error("'" + name + "' " + why);
    };
    auto check = [&](exr_result_t result, const char* doing) {
        if (result == EXR_ERR_SUCCESS) return;
        const std::string detail =
            state.message.empty() ? exr_get_default_error_message(result) : state.message;
        throw refuse(std::string("is not a readable OpenEXR file (") + doing + ": " + detail + ")");
    };
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn          = keep_message;
    init.user_data                 = &state;
    if (from_memory) {
        init.read_fn = read_memory;
        init.size_fn = size_of_memory;
    }
    // The header is refused beyond these before the library allocates for the pixels.
    init.max_image_width  = 65536;
    init.max_image_height = 65536;
    context_guard guard;
    check(exr_start_read(&guard.context, name.c_str(), &init), "its header");

    int parts = 0;
    check(exr_get_count(guard.context, &parts), "its parts");
    if (parts != 1)
        throw refuse("has " + std::to_string(parts) + " parts: one scan-line image is read");
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    check(exr_get_storage(guard.context, 0, &storage), "its storage");
    if (storage != EXR_STORAGE_SCANLINE)
        throw refuse("is tiled or deep: only scan-line images are read");
    exr_attr_box2i_t window{};
    check(exr_get_data_window(guard.context, 0, &window), "its data window");
    const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (w <= 0 || h <= 0) throw refuse("has an empty data window");
    if (w * h > max_pixels)
        throw refuse("is " + std::to_string(w) + " x " + std::to_string(h) + ": more than " +
                     std::to_string(max_pixels) + " pixels");

    const exr_attr_chlist_t* channels = nullptr;
    check(exr_get_channels(guard.context, 0, &channels), "its channels");
    exr_pixels stored = exr_pixels::float32;
    for (const char* wanted : channel_names) {
        const exr_attr_chlist_entry_t* found = nullptr;
        for (int i = 0; i < channels->num_channels; ++i)
            if (std::strcmp(channels->entries[i].name.str, wanted) == 0)
                found = &channels->entries[i];
        if (!found) throw refuse(std::string("has no channel ") + wanted);
        if (found->pixel_type == EXR_PIXEL_UINT)
            throw refuse(std::string("has integers in channel ") + wanted + ", not floats");
        if (found->x_sampling != 1 || found->y_sampling != 1)
            throw refuse(std::string("has channel ") + wanted + " subsampled");
        if (found->pixel_type == EXR_PIXEL_HALF) stored = exr_pixels::half16;
    }

    int32_t lines_per_chunk = 0;
    check(exr_get_scanlines_per_chunk(guard.context, 0, &lines_per_chunk), "its chunks");
    if (lines_per_chunk <= 0) throw refuse("has no scan lines per chunk");
    std::vector<float> rgb(std::size_t(w) * std::size_t(h) * 3);
    bool routines_chosen = false;
    for (long long y = window.min.y; y <= window.max.y; y += lines_per_chunk) {
        exr_chunk_info_t chunk{};
        check(exr_read_scanline_chunk_info(guard.context, 0, int(y), &chunk), "a block of lines");
        if (chunk.start_y < window.min.y || chunk.height <= 0 ||
            static_cast<long long>(chunk.start_y) + chunk.height - 1 > window.max.y)
            throw refuse("has a block of lines outside its data window");
        if (!guard.decoding) {
            check(exr_decoding_initialize(guard.context, 0, &chunk, &guard.decoder),
                  "a block of lines");
            guard.decoding = true;
        } else {
            check(exr_decoding_update(guard.context, 0, &chunk, &guard.decoder),
                  "a block of lines");
        }
        for (int16_t i = 0; i < guard.decoder.channel_count; ++i) {
            exr_coding_channel_info_t& c = guard.decoder.channels[i];
            c.decode_to_ptr              = nullptr;  // a channel not asked for is skipped
            for (std::size_t k = 0; k < channel_names.size(); ++k) {
                if (std::strcmp(c.channel_name, channel_names[k]) != 0) continue;
                const std::size_t first =
                    (std::size_t(chunk.start_y - window.min.y) * std::size_t(w)) * 3 + k;
                c.decode_to_ptr          = reinterpret_cast<uint8_t*>(rgb.data() + first);
                c.user_pixel_stride      = int32_t(3 * sizeof(float));
                c.user_line_stride       = int32_t(3 * sizeof(float) * std::size_t(w));
                c.user_data_type         = EXR_PIXEL_FLOAT;
                c.user_bytes_per_element = int16_t(sizeof(float));
            }
        }
        if (!routines_chosen) {  // by the first block's channels; the same for every block
            check(exr_decoding_choose_default_routines(guard.context, 0, &guard.decoder),
                  "a block of lines");
            routines_chosen = true;
        }
        check(exr_decoding_run(guard.context, 0, &guard.decoder), "a block of lines");
    }

    exr_image out{image(int(w), int(h)), stored};
    for (int y = 0; y < int(h); ++y)
        for (int x = 0; x < int(w); ++x) {
            const float* p = &rgb[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3];
            out.pixels.set(x, y, color(p[0], p[1], p[2]));
        }
    return out;
}

}  // namespace

exr_image read_exr(const std::string& path, long long max_pixels) {
    read_state state;
    return read_exr_with(path, state, false, max_pixels);
}

exr_image read_exr_bytes(const void* data, std::size_t size, const std::string& name,
                         long long max_pixels) {
    read_state state;
    state.data = static_cast<const char*>(data);
    state.size = size;
    return read_exr_with(name, state, true, max_pixels);
}

}  // namespace rt
