// Checking a property value against its declaration (type, range, options, portable paths): the
// registry's checks, apart from the declarations in property_registry.cpp.
#include "scene/property_registry.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

// Index of the variant alternative a property type travels in.
size_t alternativeFor(PropertyType type) {
    switch (type) {
    case PropertyType::Bool: return 0;
    case PropertyType::Int: return 1;
    case PropertyType::Float: return 2;
    case PropertyType::Vec2: return 3;
    case PropertyType::Vec3:
    case PropertyType::Color: return 4;
    case PropertyType::String:
    case PropertyType::Enum:
    case PropertyType::Path: return 5;
    case PropertyType::IdRef: return 6;
    }
    return 0;
}

bool inRange(const PropertyInfo& info, double v) {
    return std::isfinite(v) && v >= info.min && v <= info.max;
}

} // namespace

bool isPortableRelativePath(const std::string& path) {
    if (path.empty()) return true;
    if (path[0] == '/' || path[0] == '\\' || path[0] == '~') return false;
    // Windows drive letters ("C:/...") are absolute too.
    if (path.size() >= 2 && path[1] == ':') return false;
    return true;
}

util::Status checkValue(const PropertyInfo& info, const PropertyValue& value) {
    auto fail = [&](const std::string& why) {
        return makeError(ErrorKind::Invalid, "", info.name + ": " + why);
    };
    if (value.index() != alternativeFor(info.type))
        return fail(std::string("expected a ") + propertyTypeName(info.type) + ", got " + formatValue(value));
    // Appends, not `"[" + std::string`: that form trips GCC 12's -Wrestrict false positive here.
    std::string range(1, '[');
    range += formatValue(float(info.min)) + ", " + formatValue(float(info.max)) + "]";
    switch (info.type) {
    case PropertyType::Int:
        if (!inRange(info, std::get<int>(value))) return fail(formatValue(value) + " is outside " + range);
        break;
    case PropertyType::Float:
        if (!inRange(info, std::get<float>(value))) return fail(formatValue(value) + " is outside " + range);
        break;
    case PropertyType::Vec2: {
        const glm::vec2 v = std::get<glm::vec2>(value);
        if (!inRange(info, v.x) || !inRange(info, v.y)) return fail(formatValue(value) + " is outside " + range);
        break;
    }
    case PropertyType::Vec3:
    case PropertyType::Color: {
        const glm::vec3 v = std::get<glm::vec3>(value);
        for (int c = 0; c < 3; ++c)
            if (!inRange(info, v[c])) return fail(formatValue(value) + " is outside " + range);
        break;
    }
    case PropertyType::Enum: {
        const auto& s = std::get<std::string>(value);
        if (std::find(info.enumOptions.begin(), info.enumOptions.end(), s) == info.enumOptions.end())
            return fail(unknownOptionMessage(info, s));
        break;
    }
    case PropertyType::Path:
        if (!isPortableRelativePath(std::get<std::string>(value)))
            return fail("absolute path '" + std::get<std::string>(value) +
                        "' not allowed: paths are relative to the file");
        break;
    default: break;
    }
    return util::okStatus();
}

std::string unknownOptionMessage(const PropertyInfo& info, const std::string& value) {
    std::string all;
    for (const auto& o : info.enumOptions) all += (all.empty() ? "" : ", ") + o;
    if (info.enumNoun.empty()) return "'" + value + "' is not one of " + all;
    return "unknown " + info.enumNoun + " '" + value + "'; known: " + all;
}

} // namespace wavelit::scene
