// The header of a PLY file as Assimp 5.2's PLY reader reads it (what Debian 12 ships): the
// elements, their counts and their properties. checkPlyFile (mesh_loader_ply.h) walks the element
// data with it; a header read differently from Assimp made that walk miss what Assimp allocates
// (fuzz_ply findings), so this reader follows Assimp's rules, each named where it applies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::scene {

enum class PlyType { Unknown, Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// The scalar type names Assimp 5.2 knows (Unknown for others).
PlyType plyType(const std::string& name);
// Size in bytes of a binary value; 0 for Unknown.
uint64_t plyTypeSize(PlyType t);

struct PlyProperty {
    std::string name, typeName;
    bool list = false;
    PlyType lengthType = PlyType::Unknown, type = PlyType::Unknown; // type: the list's items
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;       // an upper bound of what Assimp may read: for the size bounds
    uint64_t assimpCount = 0; // what Assimp reads: for the walks
    std::vector<PlyProperty> properties;
    uint64_t minBytes() const { // a list counts its length field only: its items may be none
        uint64_t bytes = 0;
        for (const PlyProperty& p : properties) bytes += plyTypeSize(p.list ? p.lengthType : p.type);
        return bytes;
    }
};

struct PlyHeader {
    std::string format;
    uint64_t bytes = 0;         // the header's bytes, through the '\n' after end_header (binary data follow)
    uint64_t firstDataLine = 0; // where Assimp's line reader goes on after end_header (ascii data)
    bool ended = false, unterminatedEnd = false;
    std::string malformed; // the first element line that is not "element NAME COUNT"
    std::vector<PlyElement> elements;
};

// Assimp 5.2's line reader (IOStreamBuffer::getNextLine) over a file's bytes: a line ends at the
// first of '\n', '\r', '\f', '\0', which is consumed; when the next line would start on another of
// those, everything up to and including the next '\n' is skipped first (so "1\0" "5\n" is two lines,
// "1\0\0" "5\n" one: the "5" is lost; and a second empty line in a row is a line). Each line Assimp
// reads, in the header as in the data, is one of these.
class AssimpLines {
public:
    AssimpLines(const std::string& bytes, size_t at) : m_bytes(bytes), m_at(at) {}
    // The next line, or false at the end of the bytes.
    bool next(std::string& line);
    size_t start() const { return m_start; }        // where the last line starts
    size_t at() const { return m_at; }              // just past its line end
    bool startsAfterNewline() const { return m_start == 0 || m_bytes[m_start - 1] == '\n'; }
    uint64_t lineNumber() const { return m_newlines + 1; } // of the last line's start, counted in '\n's

private:
    const std::string& m_bytes;
    size_t m_at, m_start = 0, m_counted = 0;
    uint64_t m_newlines = 0;
};

// The header at the start of `bytes` (at most its first MiB is read).
PlyHeader readPlyHeader(const std::string& bytes);

} // namespace wavelit::scene
