// ETC1S payloads with BasisLZ supercompression. The KTX2 supercompression global
// data (KTX 2.0 spec, "BasisLZ Global Data") holds the endpoint and selector
// codebooks, the four slice Huffman tables and one image descriptor per level;
// each level holds an RGB slice and optionally an alpha slice whose green channel
// is the alpha. Codebook and slice bitstreams: Binomial's ".basis File Format and
// ETC1S Texture Video Specification", sections 7 to 11.
#include <algorithm>
#include <array>

#include "basislz_bits.h"
#include "ktx2_basis.h"

namespace sherpa::tex {

namespace {
using basislz::BitReader;
using basislz::Huffman;

struct Endpoint {
    std::uint8_t color5[3];
    std::uint8_t inten; // ETC1 intensity table index
};
struct Selector {
    std::uint8_t rows[4]; // row y: texel x in bits 2x..2x+1
    unsigned at(unsigned x, unsigned y) const { return (rows[y] >> (2 * x)) & 3u; }
};
struct Codebooks {
    std::vector<Endpoint> endpoints;
    std::vector<Selector> selectors;
    Huffman endpoint_pred, delta_endpoint, selector, selector_history_rle;
    std::uint32_t history_size = 0;
};

std::uint32_t le32(std::span<const std::uint8_t> in, std::size_t at) {
    return std::uint32_t{in[at]} | std::uint32_t{in[at + 1]} << 8 |
           std::uint32_t{in[at + 2]} << 16 | std::uint32_t{in[at + 3]} << 24;
}

bool read_endpoints(std::span<const std::uint8_t> data, std::size_t count,
                    std::vector<Endpoint>& out, std::string& error) {
    BitReader in(data);
    Huffman color[3], inten;
    for (Huffman* h : {&color[0], &color[1], &color[2], &inten})
        if (!read_huffman(in, *h, error)) return error = "endpoint codebook: " + error, false;
    const bool grey = in.bits(1) != 0;
    std::uint8_t prev[3] = {16, 16, 16};
    unsigned prev_inten = 0;
    out.resize(count);
    for (Endpoint& e : out) {
        const int di = inten.decode(in);
        if (di < 0) return error = "endpoint codebook: truncated or corrupt", false;
        e.inten = static_cast<std::uint8_t>((unsigned(di) + prev_inten) & 7);
        prev_inten = e.inten;
        for (unsigned c = 0; c < (grey ? 1u : 3u); ++c) {
            // The delta's table depends on the previous value (spec 7.0).
            const Huffman& h = prev[c] <= 9 ? color[0] : prev[c] <= 21 ? color[1] : color[2];
            const int delta = h.decode(in);
            if (delta < 0) return error = "endpoint codebook: truncated or corrupt", false;
            prev[c] = e.color5[c] = static_cast<std::uint8_t>((prev[c] + delta) & 31);
        }
        if (grey) e.color5[1] = e.color5[2] = e.color5[0];
    }
    return true;
}

bool read_selectors(std::span<const std::uint8_t> data, std::size_t count,
                    std::vector<Selector>& out, std::string& error) {
    BitReader in(data);
    if (in.bits(1) || in.bits(1))
        return error = "selector codebook: global/hybrid codebooks are not part of KTX2", false;
    const bool raw = in.bits(1) != 0;
    Huffman delta;
    if (!raw && !read_huffman(in, delta, error))
        return error = "selector codebook: " + error, false;
    out.resize(count);
    std::uint8_t prev[4] = {};
    for (std::size_t i = 0; i < count; ++i)
        for (unsigned row = 0; row < 4; ++row) {
            unsigned byte;
            if (raw || i == 0)
                byte = in.bits(8);
            else {
                const int d = delta.decode(in);
                if (d < 0) return error = "selector codebook: truncated or corrupt", false;
                byte = unsigned(d) ^ prev[row];
            }
            prev[row] = out[i].rows[row] = static_cast<std::uint8_t>(byte);
        }
    if (in.overrun()) return error = "selector codebook: truncated", false;
    return true;
}

bool read_tables(std::span<const std::uint8_t> data, Codebooks& books, std::string& error) {
    BitReader in(data);
    for (Huffman* h : {&books.endpoint_pred, &books.delta_endpoint, &books.selector,
                       &books.selector_history_rle})
        if (!read_huffman(in, *h, error)) return error = "slice tables: " + error, false;
    books.history_size = in.bits(13);
    if (in.overrun()) return error = "slice tables: truncated", false;
    return true;
}

// Spec 10.1: approximate move-to-front list of recently used selector indices.
class SelectorHistory {
public:
    explicit SelectorHistory(std::size_t n) : values_(n), rover_(n / 2) {}
    std::size_t size() const { return values_.size(); }
    std::uint32_t operator[](std::size_t i) const { return values_[i]; }
    void add(std::uint32_t v) {
        values_[rover_++] = v;
        if (rover_ == values_.size()) rover_ = values_.size() / 2;
    }
    void use(std::size_t i) {
        if (i) std::swap(values_[i / 2], values_[i]);
    }

private:
    std::vector<std::uint32_t> values_;
    std::size_t rover_;
};

// Spec 10.3 (without texture video): the endpoint and selector index of every
// block of a slice, in raster order.
bool decode_slice(std::span<const std::uint8_t> data, const Codebooks& books, std::uint32_t bw,
                  std::uint32_t bh, std::vector<Endpoint>& block_endpoints,
                  std::vector<Selector>& block_selectors, std::string& error) {
    BitReader in(data);
    struct Pred {
        std::uint16_t endpoint = 0;
        std::uint8_t bits = 0;
    };
    std::vector<Pred> preds[2] = {std::vector<Pred>(bw), std::vector<Pred>(bw)};
    const std::size_t selector_count = books.selectors.size();
    const std::size_t endpoint_count = books.endpoints.size();
    const std::size_t rle_symbol = selector_count + books.history_size;
    SelectorHistory history(books.history_size);
    std::uint32_t selector_run = 0, pred_run = 0, pred_bits = 0, prev_pred_symbol = 0;
    std::uint32_t prev_endpoint = 0;
    block_endpoints.resize(std::size_t{bw} * bh), block_selectors.resize(std::size_t{bw} * bh);
    const auto fail = [&](const char* what, std::uint32_t x, std::uint32_t y) {
        error = "slice block (" + std::to_string(x) + ", " + std::to_string(y) + "): " + what;
        return false;
    };
    for (std::uint32_t y = 0; y < bh; ++y) {
        std::vector<Pred>& row = preds[y & 1];
        std::vector<Pred>& other = preds[(y & 1) ^ 1];
        for (std::uint32_t x = 0; x < bw; ++x) {
            if ((x & 1) == 0) {
                if ((y & 1) == 0) {
                    if (pred_run) {
                        --pred_run;
                        pred_bits = prev_pred_symbol;
                    } else {
                        const int sym = books.endpoint_pred.decode(in);
                        if (sym < 0) return fail("truncated or corrupt endpoint prediction", x, y);
                        if (sym == 256) { // repeat the last symbol (min. 3 times)
                            pred_run = in.vlc(4) + 3 - 1;
                            pred_bits = prev_pred_symbol;
                        } else {
                            pred_bits = prev_pred_symbol = std::uint32_t(sym);
                        }
                    }
                    other[x].bits = static_cast<std::uint8_t>(pred_bits >> 4);
                } else {
                    pred_bits = row[x].bits;
                }
            }
            const std::uint32_t pred = pred_bits & 3;
            pred_bits >>= 2;
            std::uint32_t endpoint = 0;
            if (pred == 0) {
                if (x == 0) return fail("left endpoint prediction in the first column", x, y);
                endpoint = prev_endpoint;
            } else if (pred == 1) {
                if (y == 0) return fail("upper endpoint prediction in the first row", x, y);
                endpoint = other[x].endpoint;
            } else if (pred == 2) {
                if (x == 0 || y == 0)
                    return fail("upper-left endpoint prediction on an edge", x, y);
                endpoint = other[x - 1].endpoint;
            } else {
                const int delta = books.delta_endpoint.decode(in);
                if (delta < 0) return fail("truncated or corrupt endpoint delta", x, y);
                endpoint = std::uint32_t(delta) + prev_endpoint;
                if (endpoint >= endpoint_count) endpoint -= std::uint32_t(endpoint_count);
                if (endpoint >= endpoint_count) return fail("endpoint index out of range", x, y);
            }
            row[x].endpoint = static_cast<std::uint16_t>(endpoint);
            prev_endpoint = endpoint;

            std::size_t symbol;
            if (selector_run) {
                --selector_run;
                symbol = selector_count;
            } else {
                const int sym = books.selector.decode(in);
                if (sym < 0) return fail("truncated or corrupt selector", x, y);
                symbol = std::size_t(sym);
                if (symbol == rle_symbol) {
                    const int run = books.selector_history_rle.decode(in);
                    if (run < 0) return fail("truncated or corrupt selector run", x, y);
                    selector_run = (run == 63 ? in.vlc(7) : std::uint32_t(run)) + 3 - 1;
                    symbol = selector_count;
                }
            }
            std::uint32_t selector;
            if (symbol >= selector_count) {
                const std::size_t h = symbol - selector_count;
                if (h >= history.size()) return fail("selector history index out of range", x, y);
                selector = history[h];
                history.use(h);
            } else {
                selector = std::uint32_t(symbol);
                if (history.size()) history.add(selector);
            }
            if (selector >= selector_count) return fail("selector index out of range", x, y);
            block_endpoints[std::size_t{y} * bw + x] = books.endpoints[endpoint];
            block_selectors[std::size_t{y} * bw + x] = books.selectors[selector];
        }
    }
    if (in.overrun()) return error = "slice data truncated", false;
    return true;
}

// ETC1 intensity modifier tables, ordered as ETC1S selectors index them.
constexpr int kIntensity[8][4] = {{-8, -2, 2, 8},       {-17, -5, 5, 17},    {-29, -9, 9, 29},
                                  {-42, -13, 13, 42},   {-60, -18, 18, 60},  {-80, -24, 24, 80},
                                  {-106, -33, 33, 106}, {-183, -47, 47, 183}};

// Writes the blocks' texels into `image`: RGB, or (alpha slice) green into A.
void write_texels(const std::vector<Endpoint>& endpoints, const std::vector<Selector>& selectors,
                  std::uint32_t bw, RgbaImage& image, bool alpha) {
    for (std::size_t b = 0; b < endpoints.size(); ++b) {
        const std::uint32_t bx = std::uint32_t(b % bw), by = std::uint32_t(b / bw);
        const Endpoint& e = endpoints[b];
        std::uint8_t colors[4][3];
        for (int s = 0; s < 4; ++s)
            for (int c = 0; c < 3; ++c) {
                const int base = (e.color5[c] << 3) | (e.color5[c] >> 2);
                colors[s][c] = std::uint8_t(std::clamp(base + kIntensity[e.inten][s], 0, 255));
            }
        for (std::uint32_t y = 0; y < 4 && by * 4 + y < image.height; ++y)
            for (std::uint32_t x = 0; x < 4 && bx * 4 + x < image.width; ++x) {
                const std::uint8_t* c = colors[selectors[b].at(x, y)];
                std::uint8_t* out =
                    image.pixels.data() + (std::size_t{by * 4 + y} * image.width + bx * 4 + x) * 4;
                if (alpha)
                    out[3] = c[1];
                else
                    out[0] = c[0], out[1] = c[1], out[2] = c[2];
            }
    }
}

} // namespace

bool decode_etc1s_levels(const Ktx2BasisFile& file, std::vector<RgbaImage>& levels,
                         std::string& error, std::size_t level_count) {
    const auto sgd = file.global_data;
    constexpr std::size_t kHeader = 20, kImageDesc = 20;
    const std::size_t images = file.levels.size();
    if (sgd.size() < kHeader + kImageDesc * images)
        return error = "BasisLZ global data too short (" + std::to_string(sgd.size()) +
                       " bytes for " + std::to_string(images) + " images)",
               false;
    const std::size_t endpoint_count = sgd[0] | (sgd[1] << 8);
    const std::size_t selector_count = sgd[2] | (sgd[3] << 8);
    const std::uint64_t lengths[4] = {le32(sgd, 4), le32(sgd, 8), le32(sgd, 12), le32(sgd, 16)};
    std::uint64_t at = kHeader + kImageDesc * images;
    if (lengths[0] + lengths[1] + lengths[2] + lengths[3] > sgd.size() - at)
        return error = "BasisLZ global data: codebooks and tables overrun it", false;
    if (endpoint_count == 0 || selector_count == 0)
        return error = "BasisLZ global data: empty endpoint or selector codebook", false;
    Codebooks books;
    const auto section = [&](int i) {
        const auto s = sgd.subspan(at, lengths[i]);
        at += lengths[i];
        return s;
    };
    if (!read_endpoints(section(0), endpoint_count, books.endpoints, error) ||
        !read_selectors(section(1), selector_count, books.selectors, error) ||
        !read_tables(section(2), books, error))
        return error = "BasisLZ global data: " + error, false;

    levels.resize(std::min(images, level_count));
    std::vector<Endpoint> endpoints;
    std::vector<Selector> selectors;
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const auto desc = sgd.subspan(kHeader + kImageDesc * l, kImageDesc);
        const std::string where = "level " + std::to_string(l) + ": ";
        if (le32(desc, 0) != 0) return error = where + "texture video P-frames unsupported", false;
        const Ktx2BasisLevel& level = file.levels[l];
        const std::uint32_t bw = (level.width + 3) / 4, bh = (level.height + 3) / 4;
        RgbaImage& image = levels[l];
        image.width = level.width, image.height = level.height;
        image.pixels.assign(std::size_t{level.width} * level.height * 4, 255);
        for (int slice = 0; slice < 2; ++slice) {
            const std::uint64_t offset = le32(desc, 4 + 8 * slice),
                                length = le32(desc, 8 + 8 * slice);
            if (slice == 1 && length == 0) {
                if (file.has_alpha) return error = where + "alpha slice missing", false;
                break;
            }
            if (offset > level.bytes.size() || length > level.bytes.size() - offset)
                return error = where + "slice overruns the level", false;
            if (!decode_slice(level.bytes.subspan(offset, length), books, bw, bh, endpoints,
                              selectors, error))
                return error = where + (slice ? "alpha " : "RGB ") + error, false;
            write_texels(endpoints, selectors, bw, image, slice == 1);
        }
    }
    return true;
}

} // namespace sherpa::tex
