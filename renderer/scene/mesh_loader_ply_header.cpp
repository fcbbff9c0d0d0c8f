#include "scene/mesh_loader_ply_header.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>

namespace wavelit::scene {

PlyType plyType(const std::string& t) {
    if (t == "char" || t == "int8") return PlyType::Int8;
    if (t == "uchar" || t == "uint8") return PlyType::UInt8;
    if (t == "short" || t == "int16") return PlyType::Int16;
    if (t == "ushort" || t == "uint16") return PlyType::UInt16;
    if (t == "int" || t == "int32") return PlyType::Int32;
    if (t == "uint" || t == "uint32") return PlyType::UInt32;
    if (t == "float" || t == "float32") return PlyType::Float32;
    if (t == "double" || t == "float64") return PlyType::Float64;
    return PlyType::Unknown;
}

uint64_t plyTypeSize(PlyType t) {
    switch (t) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    default: return 0;
    }
}

namespace {

// The words of a header line as Assimp splits them (at spaces and tabs only).
std::vector<std::string> headerWords(const std::string& line) {
    std::vector<std::string> words;
    for (size_t at = 0; at < line.size();) {
        const size_t end = std::min(line.size(), line.find_first_of(" \t", at));
        if (end > at) words.push_back(line.substr(at, end - at));
        at = end + 1;
    }
    return words;
}

// Assimp's strtoul10: the leading digits of `word`, wrapping at 32 bits.
uint32_t leadingNumber(const std::string& word) {
    uint32_t v = 0;
    for (size_t i = 0; i < word.size() && word[i] >= '0' && word[i] <= '9'; ++i) v = v * 10u + uint32_t(word[i] - '0');
    return v;
}

// One header line other than end_header.
void readHeaderLine(PlyHeader& h, bool& inElement, const std::string& line) {
    const std::vector<std::string> words = headerWords(line);
    const std::string word = words.empty() ? "" : words[0];
    auto wordAt = [&](size_t i) { return i < words.size() ? words[i] : std::string(); };
    if (word == "comment") return;
    const bool property = word == "property";
    if (property && inElement) {
        PlyProperty p;
        p.typeName = wordAt(1);
        if (p.typeName == "list") {
            p.list = true;
            p.lengthType = plyType(wordAt(2));
            p.type = plyType(wordAt(3));
            p.typeName = "list " + wordAt(2) + " " + wordAt(3);
            p.name = wordAt(4);
        } else {
            p.type = plyType(p.typeName);
            p.name = wordAt(2);
        }
        h.elements.back().properties.push_back(p);
    }
    inElement = inElement && property;
    if (word == "format" && h.format.empty()) {
        h.format = wordAt(1);
    } else if (word == "element") {
        // "element NAME COUNT" and nothing else: Assimp read the count of a shorter element line
        // from the leftovers of a longer line before it in its line buffer (3817748707 instances,
        // 91 GB: fuzz_ply finding).
        if (h.malformed.empty() && (words.size() != 3 || wordAt(2).find_first_not_of("0123456789") != std::string::npos))
            h.malformed = line;
        PlyElement e;
        e.name = wordAt(1);
        // Assimp reads the count after the names it knows, and from the name itself otherwise
        // ("element 4444...4vertex 4": fuzz_ply finding), as a 32-bit value that wraps; the size
        // bounds take the larger of that and the count as written.
        static const char* known[] = {"vertex", "face", "tristrips", "edge", "material"};
        const bool knownName = std::find(std::begin(known), std::end(known), e.name) != std::end(known);
        e.assimpCount = knownName ? leadingNumber(wordAt(2)) : e.name == "TextureFile" ? 0 : leadingNumber(e.name);
        const long long written = std::strtoll(wordAt(2).c_str(), nullptr, 10);
        e.count = std::min<uint64_t>(std::max<uint64_t>(uint64_t(std::max(0LL, written)), e.assimpCount), uint64_t(1) << 40);
        h.elements.push_back(e);
        inElement = true;
    }
}

} // namespace

bool AssimpLines::next(std::string& line) {
    auto lineEnd = [&](size_t i) { return m_bytes[i] == '\n' || m_bytes[i] == '\r' || m_bytes[i] == '\f' || m_bytes[i] == '\0'; };
    if (m_at < m_bytes.size() && lineEnd(m_at)) {
        const size_t newline = m_bytes.find('\n', m_at);
        m_at = newline == std::string::npos ? m_bytes.size() : newline + 1;
    }
    if (m_at >= m_bytes.size()) return false;
    m_start = m_at;
    while (m_at < m_bytes.size() && !lineEnd(m_at)) ++m_at;
    line.assign(m_bytes, m_start, m_at - m_start);
    for (; m_counted < m_start; ++m_counted) m_newlines += m_bytes[m_counted] == '\n';
    ++m_at; // the line end
    return true;
}

// Reads the header as Assimp 5.2 does, line by line (AssimpLines). "end_header" must also start a
// '\n'-separated line (the first PLY check's rule, kept: stricter than Assimp) and be followed by a
// '\n'. An element's properties are the property lines right after it (comments between them
// allowed): Assimp ignores a property line anywhere else, so the walks must too (a stray one, or one
// after an empty line, shifted the walk's lines against Assimp's and hid lists of gigabytes from
// it: fuzz_ply findings).
PlyHeader readPlyHeader(const std::string& bytes) {
    PlyHeader h;
    bool inElement = false;
    AssimpLines lines(bytes, 0);
    for (std::string text; lines.start() < (1u << 20) && lines.next(text);) {
        if (text.rfind("end_header", 0) == 0 && (text.size() == 10 || text[10] == ' ' || text[10] == '\t')) {
            // Without a '\n' after it (the file's last bytes), Assimp re-reads a longer header line
            // before it forever (fuzz_ply finding: "abcdefghijk\nend_header" at the end hung it).
            const size_t newline = bytes.find('\n', lines.at() - 1);
            h.ended = lines.startsAfterNewline() && newline != std::string::npos;
            h.unterminatedEnd = lines.startsAfterNewline() && newline == std::string::npos;
            h.bytes = newline == std::string::npos ? bytes.size() : newline + 1;
            h.firstDataLine = std::min(lines.at(), bytes.size());
            return h;
        }
        readHeaderLine(h, inElement, text);
    }
    return h;
}

} // namespace wavelit::scene
