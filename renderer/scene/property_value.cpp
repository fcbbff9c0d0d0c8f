#include "scene/property_value.h"

#include <cstdio>
#include <initializer_list>

namespace wavelit::scene {

namespace {
std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}
std::string list(std::initializer_list<float> values) {
    std::string out(1, '[');
    for (float v : values) {
        if (out.size() > 1) out += ", ";
        out += number(v);
    }
    out += ']';
    return out;
}

} // namespace

std::string formatValue(const PropertyValue& value) {
    struct Visitor {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(int i) const { return std::to_string(i); }
        std::string operator()(float f) const { return number(f); }
        // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
        std::string operator()(const glm::vec2& v) const { return list({v.x, v.y}); }
        std::string operator()(const glm::vec3& v) const { return list({v.x, v.y, v.z}); }
        std::string operator()(const std::string& s) const {
            std::string out(1, '"');
            out += s;
            out += '"';
            return out;
        }
        std::string operator()(EntityId id) const {
            std::string out(1, '#');
            out += std::to_string(id);
            return out;
        }
    };
    return std::visit(Visitor{}, value);
}

} // namespace wavelit::scene
