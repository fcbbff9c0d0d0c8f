#include "scene/mesh_loader_ply.h"

#include "scene/mesh_loader_ply_header.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

// A value Assimp reads as a list length of 2^32 or more (a negative signed length converted to
// unsigned, a float out of range): far more than any file holds, so one number says "too many".
constexpr uint64_t kHugeLength = uint64_t(1) << 32;

bool isSigned(PlyType t) { return t == PlyType::Int8 || t == PlyType::Int16 || t == PlyType::Int32; }
bool isFloat(PlyType t) { return t == PlyType::Float32 || t == PlyType::Float64; }

// What Assimp makes of a float read as a list length (a cast to unsigned int, undefined out of range).
uint64_t lengthFromFloat(double v) { return v >= 0.0 && v < double(kHugeLength) ? uint64_t(v) : kHugeLength; }

// Sequential reads over a file with a block buffer (a binary walk reads a list length per face).
class ByteWalker {
public:
    ByteWalker(std::istream& in, uint64_t size, uint64_t at) : m_in(in), m_size(size), m_at(at), m_block(1 << 16) {}
    uint64_t at() const { return m_at; }
    uint64_t left() const { return m_size - m_at; }
    bool skip(uint64_t n) {
        if (n > left()) return false;
        m_at += n;
        return true;
    }
    // The next n (<= 8) bytes as a little-endian unsigned value, or false past the end.
    bool read(size_t n, bool bigEndian, uint64_t& value) {
        if (n > left()) return false;
        value = 0;
        for (size_t i = 0; i < n; ++i) {
            if (m_at < m_start || m_at >= m_start + m_filled) fill();
            const uint64_t byte = uint8_t(m_block[size_t(m_at - m_start)]);
            value |= byte << (8 * (bigEndian ? n - 1 - i : i));
            ++m_at;
        }
        return true;
    }

private:
    void fill() {
        m_start = m_at;
        m_in.clear();
        m_in.seekg(std::streamoff(m_at));
        m_in.read(m_block.data(), std::streamsize(m_block.size()));
        m_filled = uint64_t(m_in.gcount());
    }
    std::istream& m_in;
    uint64_t m_size, m_at, m_start = 0, m_filled = 0;
    std::vector<char> m_block;
};

// The list length Assimp reads from a binary value (converted to unsigned int as it does).
uint64_t binaryLength(uint64_t raw, PlyType t) {
    const uint64_t bits = 8 * plyTypeSize(t);
    if (t == PlyType::Float32) {
        float f;
        const uint32_t u = uint32_t(raw);
        std::memcpy(&f, &u, 4);
        return lengthFromFloat(f);
    }
    if (t == PlyType::Float64) {
        double d;
        std::memcpy(&d, &raw, 8);
        return lengthFromFloat(d);
    }
    if (isSigned(t) && (raw >> (bits - 1)) != 0) return kHugeLength; // negative
    return raw;
}

std::string describe(const PlyElement& e, uint64_t instance) {
    return "element '" + e.name + "' instance " + std::to_string(instance);
}

// Binary data: Assimp reads every instance of every element, and sizes each list from its stated
// length before reading the items (a face list stating 10^9 items made it allocate 8 GB: fuzz_ply
// finding). Every length is checked against the bytes left.
util::Status walkBinary(const std::string& path, std::istream& in, uint64_t size, const PlyHeader& h) {
    const bool bigEndian = h.format.size() > 7 && (h.format[7] == 'b' || h.format[7] == 'B');
    ByteWalker data(in, size, h.bytes);
    auto bad = [&](const std::string& what) { return makeError(ErrorKind::Format, path, "cannot read mesh: PLY " + what); };
    for (const PlyElement& e : h.elements) {
        for (uint64_t i = 0; i < e.assimpCount && !e.properties.empty(); ++i) {
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    if (!data.skip(plyTypeSize(p.type)))
                        return bad("data ends inside " + describe(e, i) + " (the file has " + std::to_string(size) + " bytes)");
                    continue;
                }
                uint64_t raw = 0;
                if (!data.read(size_t(plyTypeSize(p.lengthType)), bigEndian, raw))
                    return bad("data ends inside " + describe(e, i) + " (the file has " + std::to_string(size) + " bytes)");
                const uint64_t length = binaryLength(raw, p.lengthType);
                if (length > data.left() / plyTypeSize(p.type))
                    return bad(describe(e, i) + " states a list of " + std::to_string(length) + " items of " +
                               std::to_string(plyTypeSize(p.type)) + " bytes at byte " + std::to_string(data.at()) +
                               ", but only " + std::to_string(data.left()) + " bytes follow");
                data.skip(length * plyTypeSize(p.type));
            }
        }
    }
    return util::okStatus();
}

// One ascii value as Assimp's parsers read it from line[c...]: digits for unsigned types (wrapping
// at 32 bits), a sign and digits for signed ones, a number for floats. Moves c past what it reads
// (nothing, on text that is not a number: Assimp then reads the same text again) and returns the
// value as a list length.
uint64_t readAsciiValue(const std::string& line, size_t& c, PlyType t) {
    if (isFloat(t)) { // fast_atoreal_move (assimp/fast_atof.h)
        const size_t start = c;
        auto digit = [&](size_t i) { return i < line.size() && line[i] >= '0' && line[i] <= '9'; };
        // strtoul10_64: on an overflow of 64 bits it returns 0 and leaves the cursor on the number,
        // so a list length after "1234567890123456789012345 7" is read from that number (fuzz_ply
        // findings: 16-34 GB); false there.
        auto digits = [&](size_t& i) {
            const size_t first = i;
            for (uint64_t v = 0; digit(i); ++i) {
                const uint64_t next = v * 10 + uint64_t(line[i] - '0');
                if (next < v) {
                    i = first;
                    return false;
                }
                v = next;
            }
            return true;
        };
        if (c < line.size() && (line[c] == '-' || line[c] == '+')) ++c;
        const size_t number = c;
        if (line.compare(c, 3, "nan") == 0 || line.compare(c, 3, "inf") == 0 || line.compare(c, 3, "NaN") == 0 ||
            line.compare(c, 3, "INF") == 0 || line.compare(c, 3, "Inf") == 0)
            c += 3;
        else if (!digits(c) || c == number) // overflow, or not a number (Assimp throws: nothing after it matters)
            return 0;
        if (c < line.size() && (line[c] == '.' || line[c] == ',') && digit(c + 1)) {
            for (++c; digit(c);) ++c; // at most 15 digits count, the rest are skipped
        } else if (c < line.size() && line[c] == '.') {
            ++c;
        }
        if (c < line.size() && (line[c] == 'e' || line[c] == 'E')) {
            ++c;
            if (c < line.size() && (line[c] == '-' || line[c] == '+')) ++c;
            if (!digits(c)) return 0; // the exponent overflowed: the cursor stays on it
        }
        std::string text = line.substr(start, c - start);
        std::replace(text.begin(), text.end(), ',', '.');
        return lengthFromFloat(std::strtod(text.c_str(), nullptr));
    }
    bool negative = false;
    if (isSigned(t) && c < line.size() && (line[c] == '-' || line[c] == '+')) negative = line[c++] == '-';
    uint32_t wrapped = 0;
    uint64_t saturated = 0;
    for (; c < line.size() && line[c] >= '0' && line[c] <= '9'; ++c) {
        wrapped = wrapped * 10u + uint32_t(line[c] - '0');
        saturated = std::min(saturated * 10 + uint64_t(line[c] - '0'), kHugeLength);
    }
    if (negative && saturated != 0) return kHugeLength;
    return std::max<uint64_t>(wrapped, saturated); // either reading must fit
}

// Ascii data: Assimp reads one instance per line (AssimpLines) and sizes each list from its stated
// length before reading the items; a face line "1000000000 0 1 2" made it allocate 8 GB and run for
// minutes (fuzz_ply finding). It parses a line in a buffer it reuses: the line, a '\n', then what
// longer lines before it left there; after each property it skips spaces and '\r'/'\n', so a line
// that ends early lets the next property read those leftovers ("0" after a line holding
// "...2015317023" read a list of 2015317023 items: fuzz_ply finding). The walk parses the same
// buffer, and a list may not state more items than words left before the next line end.
util::Status walkAscii(const std::string& path, const std::string& bytes, const PlyHeader& h) {
    size_t e = 0;
    uint64_t instance = 0;
    auto skipEmptyElements = [&] { // an element without properties still takes a line per instance
        while (e < h.elements.size() && h.elements[e].assimpCount == 0) ++e;
    };
    skipEmptyElements();
    auto lineEnd = [](char ch) { return ch == '\n' || ch == '\r' || ch == '\f' || ch == '\0'; };
    std::string buffer; // Assimp's line buffer (zeros past the longest line so far)
    AssimpLines lines(bytes, size_t(h.firstDataLine));
    for (std::string line; e < h.elements.size() && lines.next(line);) {
        if (buffer.size() < line.size() + 2) buffer.resize(line.size() + 2, '\0');
        buffer.replace(0, line.size(), line);
        buffer[line.size()] = '\n';
        size_t c = 0;
        auto skipSpaces = [&] {
            while (buffer[c] == ' ' || buffer[c] == '\t') ++c;
            return !lineEnd(buffer[c]);
        };
        const PlyElement& element = h.elements[e];
        for (const PlyProperty& p : element.properties) {
            if (!skipSpaces()) break; // Assimp gives up on the rest of the instance
            if (!p.list) {
                readAsciiValue(buffer, c, p.type);
            } else {
                const uint64_t length = readAsciiValue(buffer, c, p.lengthType);
                uint64_t values = 0; // words left before the next line end
                for (size_t k = c; !lineEnd(buffer[k]); ++k)
                    values += buffer[k] != ' ' && buffer[k] != '\t' && (k == c || buffer[k - 1] == ' ' || buffer[k - 1] == '\t');
                if (length > values)
                    return makeError(ErrorKind::Format, path, "cannot read mesh: PLY " + describe(element, instance) + " (line " +
                                                                  std::to_string(lines.lineNumber()) + ") states a list of " +
                                                                  std::to_string(length) + " items, but the line holds " +
                                                                  std::to_string(values) + " more values");
                for (uint64_t k = 0; k < length && skipSpaces(); ++k) {
                    const size_t before = c;
                    readAsciiValue(buffer, c, p.type);
                    if (c == before) break; // stuck on text that is not a number, as Assimp is
                }
            }
            while (buffer[c] == ' ' || buffer[c] == '\t' || buffer[c] == '\r' || buffer[c] == '\n') ++c;
        }
        if (++instance == element.assimpCount) {
            ++e;
            instance = 0;
            skipEmptyElements();
        }
    }
    return util::okStatus();
}

} // namespace

// Assimp 5.2's PLY reader (fuzz_ply findings):
// - without an "end_header" line it never returns (at the end of the file it re-reads its last
//   line forever);
// - it loops once per element instance the header states, reading past the end of the file, and
//   allocates for them: "element vertex 4000000000" in a 300-byte file hung or exhausted memory;
// - it sizes every list from its stated length before reading the items.
// A file Assimp would read as PLY (a .ply, or one starting with "ply" in any case) is refused unless
// its header ends with such a line, the instances it states fit in what follows (one line each in
// ascii, their properties' smallest encoding in binary) and every list fits in what follows it.
util::Status checkPlyFile(const std::string& path, const std::string& ext) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const uint64_t size = uint64_t(in.tellg());
    in.seekg(0);
    char magic[3] = {};
    in.read(magic, 3);
    auto lower = [](char c) { return char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); };
    // A .ply goes to Assimp's PLY reader whatever it starts with (it skips leading line ends: a
    // file starting "\nply" without end_header hung it, fuzz_ply finding).
    if (ext != ".ply" && (lower(magic[0]) != 'p' || lower(magic[1]) != 'l' || lower(magic[2]) != 'y'))
        return util::okStatus();
    auto bad = [&](const std::string& what) { return makeError(ErrorKind::Format, path, "cannot read mesh: PLY " + what); };
    auto readBytes = [&](uint64_t count) { // the file's first `count` bytes
        std::string bytes(size_t(std::min(count, size)), '\0');
        in.clear();
        in.seekg(0);
        in.read(bytes.data(), std::streamsize(bytes.size()));
        return bytes;
    };

    std::string bytes = readBytes((1u << 20) + 1);
    const PlyHeader h = readPlyHeader(bytes);
    if (h.unterminatedEnd) return bad("header's 'end_header' line ends the file without a line end");
    if (!h.ended) return bad("header has no 'end_header' line");
    // Assimp's line reader splits lines at '\0', '\f' and a lone '\r' too, drops text after two line
    // ends in a row, and parses each line in a buffer holding leftovers of longer ones: header lines
    // split that way made it read an element count from a neighbouring line (3817748707 instances,
    // 91 GB: fuzz_ply finding). PLY text never holds those bytes, so the header, and ascii data,
    // may not either.
    auto strayLineEnd = [&](const std::string& text, size_t from, size_t to, const std::string& where) -> util::Status {
        for (size_t i = from; i < std::min(to, text.size()); ++i)
            if (text[i] == '\0' || text[i] == '\f' || (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n')))
                return bad(where + " holds a " + (text[i] == '\0' ? "NUL" : text[i] == '\f' ? "form feed" : "carriage return without a newline") +
                           " at byte " + std::to_string(i));
        return util::okStatus();
    };
    if (auto s = strayLineEnd(bytes, 0, size_t(h.bytes), "header"); !s) return s;
    if (!h.malformed.empty()) {
        std::string shown = h.malformed.substr(0, 40);
        for (char& ch : shown)
            if (ch < 0x20 || ch > 0x7e) ch = '?';
        return bad("header line '" + shown + (h.malformed.size() > 40 ? "..." : "") + "' is not 'element NAME COUNT'");
    }
    // Assimp 5.2 sizes its vertex and face arrays from the first element of a name and writes the
    // instances of a second one into them too: a second "element vertex 9" after "element vertex 4"
    // wrote past the array and corrupted the heap (fuzz_ply finding). Later Assimp versions refuse
    // a name stated twice; so does this check.
    for (size_t i = 0; i < h.elements.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (h.elements[j].name == h.elements[i].name)
                return bad("header states element '" + h.elements[i].name + "' twice");
    const uint64_t rest = size - std::min(size, h.bytes);
    uint64_t instances = 0, minBytes = 0;
    for (const PlyElement& e : h.elements) {
        instances += e.count;
        // At least a byte each: Assimp loops and allocates per instance even when the properties
        // take no bytes it knows of (444444444 instances of an element without known properties
        // took 8 GB: fuzz_ply finding).
        minBytes += e.count * std::max<uint64_t>(1, e.minBytes());
    }
    const bool ascii = h.format == "ascii", binary = h.format.rfind("binary", 0) == 0;
    if (ascii) {
        bytes = readBytes(size);
        if (auto s = strayLineEnd(bytes, size_t(h.bytes), bytes.size(), "ascii data"); !s) return s;
        // Lines as Assimp's reader sees them: it skips empty ones (an empty line counted here let
        // a list line go unread by the walk below while Assimp read it: fuzz_ply finding).
        uint64_t lines = 0;
        bool text = false;
        for (size_t i = size_t(h.bytes); i < bytes.size(); ++i) {
            if (bytes[i] == '\n') {
                lines += text;
                text = false;
            } else {
                text = true;
            }
        }
        lines += text;
        if (instances > lines)
            return bad("header states " + std::to_string(instances) + " element instances, but only " +
                       std::to_string(lines) + " line(s) follow it");
    } else if (binary && minBytes > rest) {
        return bad("header states elements of at least " + std::to_string(minBytes) + " bytes, but only " +
                   std::to_string(rest) + " follow it");
    }
    if (!ascii && !binary) return util::okStatus(); // Assimp refuses the format itself
    // The walks below need every value's type; Assimp drops a property of a type it does not know
    // and every property after it, so the file would not be read as written anyway.
    for (const PlyElement& e : h.elements)
        for (const PlyProperty& p : e.properties)
            if (p.type == PlyType::Unknown || (p.list && p.lengthType == PlyType::Unknown))
                return bad("property '" + p.name + "' of element '" + e.name + "' has an unknown type '" + p.typeName + "'");
    if (ascii) return walkAscii(path, bytes, h);
    if (auto s = walkBinary(path, in, size, h); !s) return s;
    // Empty lines right after end_header's line: Assimp 5.2 skips them before its binary data (an
    // empty line there hid a 27 GB list from the walk above: fuzz_ply finding), so the data after
    // them must hold what the header states too. Only '\n' and '\r': a first value whose low byte
    // is 0 (a float 0.0) is common, and no finding says Assimp skips it.
    PlyHeader skipped = h;
    auto lineEnd = [&](uint64_t i) { return i < bytes.size() && (bytes[i] == '\n' || bytes[i] == '\r'); };
    while (lineEnd(skipped.bytes)) {
        const size_t newline = bytes.find('\n', size_t(skipped.bytes));
        skipped.bytes = newline == std::string::npos ? size : newline + 1;
    }
    return skipped.bytes == h.bytes ? util::okStatus() : walkBinary(path, in, size, skipped);
}

} // namespace wavelit::scene
