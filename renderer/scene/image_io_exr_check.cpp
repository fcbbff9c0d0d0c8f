#include "scene/image_io_exr_check.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <vector>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

// The version field's flags (OpenEXR file layout).
constexpr uint32_t kMagic = 20000630, kTiledFlag = 0x200, kDeepFlag = 0x800, kMultiPartFlag = 0x1000;
// Counts past this are "more than any file holds" (and keep the sums below from overflowing).
constexpr uint64_t kHuge = uint64_t(1) << 40;

uint32_t le32(const char* p) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | uint8_t(p[i]);
    return v;
}
uint64_t le64(const char* p) { return uint64_t(le32(p)) | uint64_t(le32(p + 4)) << 32; }

// What the walks need from a part's header (attributes a header lacks keep these defaults).
struct ExrPart {
    bool hasWindow = false;
    int64_t minX = 0, minY = 0, maxX = -1, maxY = -1;
    int compression = -1;
    bool hasTiles = false;
    uint32_t tileX = 0, tileY = 0;
    uint8_t tileMode = 0;
    int64_t chunkCount = -1; // multi-part files state it (single-part ones imply it)
    std::string type;        // multi-part files state it: "scanlineimage", "tiledimage", "deep..."
};

struct ExrLayout {
    bool followed = false; // false: not an EXR this walk can follow; left to OpenEXR
    uint32_t flags = 0;
    std::vector<ExrPart> parts;
    uint64_t headersEnd = 0, size = 0;
};

util::Error fail(const std::string& path, const std::string& what) {
    return makeError(ErrorKind::Format, path, "cannot read EXR: " + what);
}

std::string printable(std::string name) { // a corrupt name is shown, not printed raw
    for (char& c : name)
        if (c < 0x20 || c > 0x7e) c = '?';
    return name.size() > 40 ? name.substr(0, 40) + "..." : name;
}

void keepAttribute(ExrPart& part, const std::string& name, const std::string& type, const std::string& v) {
    if (name == "dataWindow" && type == "box2i" && v.size() == 16) {
        part.hasWindow = true;
        part.minX = int32_t(le32(&v[0]));
        part.minY = int32_t(le32(&v[4]));
        part.maxX = int32_t(le32(&v[8]));
        part.maxY = int32_t(le32(&v[12]));
    } else if (name == "compression" && type == "compression" && v.size() == 1) {
        part.compression = uint8_t(v[0]);
    } else if (name == "tiles" && type == "tiledesc" && v.size() == 9) {
        part.hasTiles = true;
        part.tileX = le32(&v[0]);
        part.tileY = le32(&v[4]);
        part.tileMode = uint8_t(v[8]);
    } else if (name == "chunkCount" && type == "int" && v.size() == 4) {
        part.chunkCount = int32_t(le32(&v[0]));
    } else if (name == "type" && type == "string") {
        part.type = v;
    }
}

// Walks every header (OpenEXR 3.1 allocated an attribute's stated size before reading it: a 700-byte
// file stating a 1.6 GB attribute reserved 1.6 GB per load, fuzz_exr finding).
util::Status readLayout(const std::string& path, std::ifstream& in, ExrLayout& layout) {
    in.seekg(0, std::ios::end);
    layout.size = uint64_t(in.tellg());
    in.seekg(0);
    char head[8];
    if (!in.read(head, 8) || le32(head) != kMagic) return util::okStatus();
    layout.flags = le32(head + 4) & ~0xffu;
    for (int part = 0; part < 4096; ++part) {
        ExrPart p;
        for (int attributes = 0;; ++attributes) {
            std::string name, type;
            if (attributes >= 4096 || !std::getline(in, name, '\0') || name.size() > 255) return util::okStatus();
            if (name.empty()) break; // the header's end
            if (!std::getline(in, type, '\0') || type.size() > 255) return util::okStatus();
            char b[4];
            if (!in.read(b, 4)) return util::okStatus();
            const uint64_t bytes = le32(b), at = uint64_t(in.tellg());
            if (at + bytes > layout.size)
                return fail(path, "attribute '" + printable(name) + "' states " + std::to_string(bytes) + " bytes, the file has " +
                                      std::to_string(layout.size - at) + " after it");
            if (bytes <= 4096) { // the attributes kept are a few bytes long
                std::string value(size_t(bytes), '\0');
                if (!in.read(value.data(), std::streamsize(bytes))) return util::okStatus();
                keepAttribute(p, name, type, value);
            }
            in.seekg(std::streamoff(at + bytes));
        }
        layout.parts.push_back(p);
        if (!(layout.flags & kMultiPartFlag)) break;
        if (in.peek() == 0) { // an empty header ends the list of parts
            in.get();
            break;
        }
    }
    layout.headersEnd = uint64_t(in.tellg());
    layout.followed = in.good();
    return util::okStatus();
}

uint64_t saturatedProduct(uint64_t a, uint64_t b) {
    a = std::min(a, kHuge);
    b = std::min(b, kHuge);
    return b != 0 && a > kHuge / b ? kHuge : a * b;
}

uint64_t roundLog2(uint64_t x, bool up) {
    uint64_t log = 0;
    while ((uint64_t(1) << (log + 1)) <= x) ++log;
    return up && (uint64_t(1) << log) < x ? log + 1 : log;
}

// Tiles per row (or column) of each level of a side of `size` pixels (OpenEXR's level sizes).
std::vector<uint64_t> tilesPerLevel(uint64_t size, uint64_t levels, uint64_t tile, bool roundUp) {
    std::vector<uint64_t> tiles;
    for (uint64_t l = 0; l < levels; ++l) {
        uint64_t s = size >> l;
        if (roundUp && (s << l) < size) ++s;
        tiles.push_back((std::max<uint64_t>(s, 1) + tile - 1) / tile);
    }
    return tiles;
}

// The chunks a part's header implies (0: this walk cannot tell; OpenEXR decides).
uint64_t chunksOf(const ExrPart& p, bool tiled, bool multiPart) {
    if (multiPart) return p.chunkCount > 0 ? uint64_t(p.chunkCount) : 0;
    if (!p.hasWindow || p.maxX < p.minX || p.maxY < p.minY) return 0;
    const uint64_t w = uint64_t(p.maxX - p.minX + 1), h = uint64_t(p.maxY - p.minY + 1);
    if (!tiled) {
        static const uint64_t linesPerChunk[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256}; // by compression
        if (p.compression < 0 || p.compression > 9) return 0;
        return (h + linesPerChunk[p.compression] - 1) / linesPerChunk[p.compression];
    }
    const int mode = p.tileMode & 0x0f;
    const bool up = (p.tileMode >> 4) == 1;
    if (!p.hasTiles || p.tileX == 0 || p.tileY == 0 || mode > 2) return 0;
    const uint64_t xLevels = mode == 0 ? 1 : roundLog2(mode == 1 ? std::max(w, h) : w, up) + 1;
    const uint64_t yLevels = mode == 0 ? 1 : roundLog2(mode == 1 ? std::max(w, h) : h, up) + 1;
    const std::vector<uint64_t> xs = tilesPerLevel(w, xLevels, p.tileX, up), ys = tilesPerLevel(h, yLevels, p.tileY, up);
    uint64_t chunks = 0;
    if (mode == 2) { // every x level with every y level
        uint64_t sx = 0, sy = 0;
        for (uint64_t x : xs) sx += x;
        for (uint64_t y : ys) sy += y;
        return saturatedProduct(sx, sy);
    }
    for (size_t l = 0; l < xs.size(); ++l) chunks = std::min(chunks + saturatedProduct(xs[l], ys[l]), kHuge);
    return std::min(chunks, kHuge);
}

// OpenEXR 3.1 allocates a part's line buffers (bytes per line of the data window x lines per chunk)
// when it opens the file: a 1 KB DWAB file stating a 900001-pixel-wide window made it allocate
// 1.8 GB before reading a pixel (fuzz_exr finding). The pixel limit applies before it opens the file.
util::Status checkWindows(const std::string& path, const ExrLayout& layout, int maxDimension) {
    for (const ExrPart& p : layout.parts) {
        const int64_t w = p.maxX - p.minX + 1, h = p.maxY - p.minY + 1;
        if (p.hasWindow && (w > maxDimension || h > maxDimension))
            return makeError(ErrorKind::Invalid, path, std::to_string(w) + "x" + std::to_string(h) + " exceeds the " +
                                                           std::to_string(maxDimension) + " pixel limit per side");
    }
    return util::okStatus();
}

} // namespace

util::Status checkExrHeaders(const std::string& path, int maxDimension) {
    std::ifstream in(path, std::ios::binary);
    ExrLayout layout;
    if (auto s = readLayout(path, in, layout); !s) return s;
    return checkWindows(path, layout, maxDimension);
}

util::Status checkExrLayout(const std::string& path, int maxDimension) {
    std::ifstream in(path, std::ios::binary);
    ExrLayout layout;
    if (auto s = readLayout(path, in, layout); !s) return s;
    if (auto s = checkWindows(path, layout, maxDimension); !s) return s;
    if (!layout.followed || (layout.flags & kDeepFlag)) return util::okStatus(); // deep data: OpenEXR refuses it here
    const bool multiPart = layout.flags & kMultiPartFlag;
    std::vector<uint64_t> chunks;
    uint64_t total = 0;
    for (const ExrPart& p : layout.parts) {
        if (p.type.find("deep") != std::string::npos) return util::okStatus();
        const bool tiled = multiPart ? p.type == "tiledimage" : (layout.flags & kTiledFlag) != 0;
        chunks.push_back(chunksOf(p, tiled, multiPart));
        if (chunks.back() == 0) return util::okStatus();
        total = std::min(total + chunks.back(), kHuge);
    }
    // The offset tables: one 8-byte offset per chunk, right after the headers.
    const uint64_t tableEnd = layout.headersEnd + 8 * total;
    if (tableEnd > layout.size)
        return fail(path, "the header states " + std::to_string(total) + " chunks (an offset table of " + std::to_string(8 * total) +
                              " bytes), the file has " + std::to_string(layout.size - layout.headersEnd) + " after the header");
    // Each chunk: [part number], y (scan lines) or tile x, y, level x, level y, then its data size.
    std::vector<char> table(size_t(8 * total));
    in.clear();
    in.seekg(std::streamoff(layout.headersEnd));
    if (!in.read(table.data(), std::streamsize(table.size()))) return util::okStatus();
    uint64_t index = 0;
    for (size_t part = 0; part < layout.parts.size(); ++part) {
        const bool tiled = multiPart ? layout.parts[part].type == "tiledimage" : (layout.flags & kTiledFlag) != 0;
        const uint64_t headerBytes = (multiPart ? 4 : 0) + (tiled ? 16 : 4) + 4;
        for (uint64_t c = 0; c < chunks[part]; ++c, ++index) {
            const uint64_t offset = le64(&table[size_t(8 * index)]);
            const std::string which = "chunk " + std::to_string(c) + (multiPart ? " of part " + std::to_string(part) : "");
            if (offset < tableEnd || offset > layout.size || layout.size - offset < headerBytes)
                return fail(path, which + " is at byte " + std::to_string(offset) + ", outside the chunks (bytes " +
                                      std::to_string(tableEnd) + " to " + std::to_string(layout.size) + ")");
            char header[24];
            in.seekg(std::streamoff(offset));
            if (!in.read(header, std::streamsize(headerBytes))) return util::okStatus();
            const int32_t dataSize = int32_t(le32(header + headerBytes - 4));
            const uint64_t after = layout.size - offset - headerBytes;
            if (dataSize < 0 || uint64_t(dataSize) > after)
                return fail(path, which + " at byte " + std::to_string(offset) + " states " + std::to_string(dataSize) +
                                      " bytes of data, the file has " + std::to_string(after) + " after its header");
        }
    }
    return util::okStatus();
}

} // namespace wavelit::scene
