#include "scene/property_json.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace wavelit::scene {

using util::ErrorKind;

namespace {

// Floats are written with their shortest round-tripping decimal form ("0.2", not
// "0.20000000298023224"): files stay readable and float -> text -> float is exact.
Json floatToJson(float f) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
    double d = 0.0;
    std::from_chars(buf, end, d);
    return Json(d);
}

util::Result<float> readFloat(const Json& v, const PropertyInfo& info, const JsonPlace& at) {
    if (!v.is_number())
        return jsonError(ErrorKind::Format, at, info.name + ": expected a number, got " + jsonTypeName(v));
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > double(std::numeric_limits<float>::max()))
        return jsonError(ErrorKind::Invalid, at, info.name + ": number out of float range");
    return float(d);
}

template <int N>
util::Result<glm::vec<N, float>> readVector(const Json& v, const PropertyInfo& info, const JsonPlace& at) {
    if (!v.is_array() || v.size() != size_t(N))
        return jsonError(ErrorKind::Format, at,
                         info.name + ": expected an array of " + std::to_string(N) + " numbers, got " +
                             (v.is_array() ? "an array of " + std::to_string(v.size()) : std::string(jsonTypeName(v))));
    glm::vec<N, float> out{};
    for (int i = 0; i < N; ++i) {
        auto f = readFloat(v[size_t(i)], info, at.child(size_t(i)));
        if (!f) return f.error();
        out[i] = *f;
    }
    return out;
}

} // namespace

util::Error jsonError(ErrorKind kind, const JsonPlace& at, const std::string& reason) {
    return util::makeError(kind, at.file, reason, at.where.empty() ? "/" : at.where);
}

const char* jsonTypeName(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    default: return "an unsupported value";
    }
}

util::Result<PropertyValue> valueFromJson(const Json& v, const PropertyInfo& info, const JsonPlace& at) {
    auto wrong = [&](const char* expected) {
        return jsonError(ErrorKind::Format, at, info.name + ": expected " + expected + ", got " + jsonTypeName(v));
    };
    PropertyValue value;
    switch (info.type) {
    case PropertyType::Bool:
        if (!v.is_boolean()) return wrong("true or false");
        value = v.get<bool>();
        break;
    case PropertyType::Int:
        if (!v.is_number_integer()) return wrong("an integer");
        if (v.get<int64_t>() < std::numeric_limits<int>::min() || v.get<int64_t>() > std::numeric_limits<int>::max())
            return jsonError(ErrorKind::Invalid, at, info.name + ": integer out of range");
        value = int(v.get<int64_t>());
        break;
    case PropertyType::Float: {
        auto f = readFloat(v, info, at);
        if (!f) return f.error();
        value = *f;
        break;
    }
    case PropertyType::Vec2: {
        auto r = readVector<2>(v, info, at);
        if (!r) return r.error();
        value = glm::vec2(*r);
        break;
    }
    case PropertyType::Vec3:
    case PropertyType::Color: {
        auto r = readVector<3>(v, info, at);
        if (!r) return r.error();
        value = glm::vec3(*r);
        break;
    }
    case PropertyType::String:
    case PropertyType::Enum:
    case PropertyType::Path:
        if (!v.is_string()) return wrong("a string");
        value = v.get<std::string>();
        break;
    case PropertyType::IdRef:
        if (!v.is_number_unsigned() || v.get<uint64_t>() == kInvalidId) return wrong("a positive integer id");
        value = EntityId(v.get<uint64_t>());
        break;
    }
    if (auto s = checkValue(info, value); !s) return jsonError(s.error().kind, at, s.error().reason);
    return value;
}

Json valueToJson(const PropertyValue& value) {
    struct Visitor {
        Json operator()(bool b) const { return Json(b); }
        Json operator()(int i) const { return Json(i); }
        Json operator()(float f) const { return floatToJson(f); }
        Json operator()(const glm::vec2& v) const { return Json::array({floatToJson(v.x), floatToJson(v.y)}); }
        Json operator()(const glm::vec3& v) const {
            return Json::array({floatToJson(v.x), floatToJson(v.y), floatToJson(v.z)});
        }
        Json operator()(const std::string& s) const { return Json(s); }
        Json operator()(EntityId id) const { return Json(id); }
    };
    return std::visit(Visitor{}, value);
}

util::Status readProperties(const Json& obj, EntityKind kind, void* entity, const JsonPlace& at,
                            const std::set<std::string>& structural, std::vector<std::string>* warnings) {
    if (!obj.is_object())
        return jsonError(ErrorKind::Format, at,
                         std::string("expected a ") + entityKindName(kind) + " object, got " + jsonTypeName(obj));
    for (const PropertyInfo& info : properties(kind)) {
        auto it = obj.find(info.name);
        if (it == obj.end()) {
            if (info.required)
                return jsonError(ErrorKind::Invalid, at,
                                 std::string(entityKindName(kind)) + " is missing required key '" + info.name + "'");
            continue;
        }
        auto value = valueFromJson(*it, info, at.child(info.name));
        if (!value) return value.error();
        info.set(entity, *value);
    }
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (!findProperty(kind, it.key()) && !structural.count(it.key()) && warnings)
            warnings->push_back(at.file + ":" + (at.where.empty() ? "/" : at.where) + ": unknown key '" +
                                it.key() + "' ignored");
    return util::okStatus();
}

void writeProperties(Json& obj, EntityKind kind, const void* entity) {
    for (const PropertyInfo& info : properties(kind))
        if (propertyApplies(info, entity)) obj[info.name] = valueToJson(info.get(entity));
}

} // namespace wavelit::scene
