// The header of a PLY file as Assimp 5.2's PLY reader reads it (what Debian 12 ships): the
// elements, their counts and their properties. checkPlyFile (mesh_loader_ply.h) walks the element
// data with it; a header read differently from Assimp made that walk miss what Assimp allocates
// (fuzz_ply findings), so this reader follows Assimp's rules, each named where it applies.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <utility>
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
    uint64_t bytes = 0, lines = 0;
    bool ended = false, unterminatedEnd = false;
    std::vector<PlyElement> elements;
};

PlyHeader readPlyHeader(std::istream& in);

// The lines Assimp 5.2 sees in one '\n'-separated line of a file, with their offsets in it: it ends
// a line at any of '\n', '\r', '\f' and '\0' and skips empty ones (a data line "1 0 0\r0 1 0" is
// two vertices to it).
std::vector<std::pair<size_t, std::string>> assimpLines(const std::string& line);

} // namespace wavelit::scene
