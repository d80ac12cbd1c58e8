#include "basislz_bits.h"

#include <algorithm>

namespace sherpa::tex::basislz {

std::uint32_t BitReader::bits(unsigned n) {
    std::uint32_t v = 0;
    for (unsigned i = 0; i < n; ++i, ++bit_) {
        if (bit_ / 8 >= bytes_.size()) {
            overrun_ = true;
            return 0;
        }
        v |= std::uint32_t{(bytes_[bit_ / 8] >> (bit_ % 8)) & 1u} << i;
    }
    return v;
}

std::uint32_t BitReader::vlc(unsigned chunk_bits) {
    const std::uint32_t chunk = 1u << chunk_bits;
    std::uint32_t v = 0;
    for (unsigned shift = 0; shift < 32 && !overrun_; shift += chunk_bits) {
        const std::uint32_t s = bits(chunk_bits + 1);
        v |= (s & (chunk - 1)) << shift;
        if (!(s & chunk)) break;
    }
    return v;
}

bool Huffman::build(const std::vector<std::uint8_t>& lengths) {
    std::fill(std::begin(count_), std::end(count_), 0);
    for (std::uint8_t l : lengths) ++count_[l];
    count_[0] = 0;
    // Over-subscription check: at each length, codes left must stay >= 0.
    int left = 1;
    for (int l = 1; l <= 16; ++l) {
        left = left * 2 - count_[l];
        if (left < 0) return false;
    }
    // A table without any code is legal until a symbol is read from it (an
    // encoder may send one for a model it never uses); decode() then fails.
    std::uint16_t offset[18] = {};
    for (int l = 1; l <= 16; ++l) offset[l + 1] = offset[l] + count_[l];
    sorted_.assign(offset[17], 0);
    for (std::size_t s = 0; s < lengths.size(); ++s)
        if (lengths[s]) sorted_[offset[lengths[s]]++] = static_cast<std::uint16_t>(s);
    return true;
}

int Huffman::decode(BitReader& in) const {
    int code = 0, first = 0, index = 0;
    for (int l = 1; l <= 16; ++l) {
        code |= static_cast<int>(in.bits(1));
        if (in.overrun()) return -1;
        const int count = count_[l];
        if (code - first < count) return sorted_[std::size_t(index + code - first)];
        index += count, first += count;
        first <<= 1, code <<= 1;
    }
    return -1;
}

bool read_huffman(BitReader& in, Huffman& out, std::string& error) {
    constexpr unsigned kMaxSymbols = 1u << 14;
    const unsigned symbols = in.bits(14), length_codes = in.bits(5);
    if (in.overrun()) return error = "Huffman table truncated", false;
    if (symbols == 0 || symbols > kMaxSymbols || length_codes == 0 || length_codes > 21)
        return error = "bad Huffman table header (" + std::to_string(symbols) + " symbols, " +
                       std::to_string(length_codes) + " code length codes)",
               false;
    static constexpr std::uint8_t kOrder[21] = {17, 18, 19, 20, 0,  8, 7,  9, 6,  10, 5,
                                                11, 4,  12, 3,  13, 2, 14, 1, 15, 16};
    std::vector<std::uint8_t> meta(21, 0);
    for (unsigned i = 0; i < length_codes; ++i) meta[kOrder[i]] = std::uint8_t(in.bits(3));
    Huffman lengths_code;
    if (in.overrun() || !lengths_code.build(meta))
        return error = "bad Huffman code length code", false;
    std::vector<std::uint8_t> lengths;
    lengths.reserve(symbols);
    while (lengths.size() < symbols) {
        const int sym = lengths_code.decode(in);
        if (sym < 0) return error = "truncated or corrupt Huffman code lengths", false;
        if (sym <= 16) {
            lengths.push_back(std::uint8_t(sym));
            continue;
        }
        unsigned run = 0;
        std::uint8_t value = 0;
        if (sym == 17)
            run = in.bits(3) + 3;
        else if (sym == 18)
            run = in.bits(7) + 11;
        else {
            if (lengths.empty() || lengths.back() == 0)
                return error = "Huffman code length repeat without a previous length", false;
            value = lengths.back();
            run = sym == 19 ? in.bits(2) + 3 : in.bits(7) + 7;
        }
        if (in.overrun() || run > symbols - lengths.size())
            return error = "Huffman code length run overruns the table", false;
        lengths.insert(lengths.end(), run, value);
    }
    if (!out.build(lengths)) return error = "over-subscribed Huffman code", false;
    return true;
}

} // namespace sherpa::tex::basislz
