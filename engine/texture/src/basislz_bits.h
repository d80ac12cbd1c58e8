#pragma once
// Bit-level reading for BasisLZ (Binomial's ".basis File Format and ETC1S
// Texture Video Specification", sections 6 and 10.2): an LSB-first bit reader
// that never reads past its span, and Deflate-style canonical Huffman tables
// whose code lengths are themselves RLE + Huffman coded.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sherpa::tex::basislz {

class BitReader {
public:
    explicit BitReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    // Reads `n` <= 32 bits, first bit lowest. Past the end: returns 0 and
    // sets overrun(), so callers check once after a batch of reads.
    std::uint32_t bits(unsigned n);
    bool overrun() const { return overrun_; }
    // Spec 10.2: chunks of `chunk_bits` bits, each followed by a "more" bit.
    std::uint32_t vlc(unsigned chunk_bits);

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t bit_ = 0;
    bool overrun_ = false;
};

// Canonical Huffman code (Deflate, RFC 1951 3.2.2): codes are assigned by
// increasing length, then symbol; the first bit read is the code's top bit.
class Huffman {
public:
    // False when the lengths over-subscribe the code space.
    bool build(const std::vector<std::uint8_t>& lengths);
    // Next symbol, or -1 for a code that no symbol has (or data overrun).
    int decode(BitReader& in) const;

private:
    std::uint16_t count_[17] = {};      // codes of each length
    std::vector<std::uint16_t> sorted_; // symbols by (length, value)
};

// Reads one compressed Huffman table (spec section 6.0) into `out`.
bool read_huffman(BitReader& in, Huffman& out, std::string& error);

} // namespace sherpa::tex::basislz
