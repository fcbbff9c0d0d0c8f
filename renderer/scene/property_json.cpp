#include "scene/property_json.h"

#include <algorithm>
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
        // Unsigned values past INT64_MAX would wrap to negatives in get<int64_t>().
        if ((v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(std::numeric_limits<int>::max())) ||
            v.get<int64_t>() < std::numeric_limits<int>::min() || v.get<int64_t>() > std::numeric_limits<int>::max())
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

namespace {

// Edit distance counting an insertion, deletion, substitution or swap of neighbours as one edit
// (optimal string alignment), ASCII case folded: "nmae" is one edit from "name", "basecolor" from
// "baseColor".
size_t editDistance(const std::string& a, const std::string& b) {
    auto same = [](char x, char y) {
        auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        return lower(x) == lower(y);
    };
    const size_t n = a.size(), m = b.size();
    std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
    for (size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (size_t i = 1; i <= n; ++i)
        for (size_t j = 1; j <= m; ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[n][m];
}

} // namespace

std::string unknownKeyProblem(const std::string& key, const JsonPlace& at, const std::vector<std::string>& known) {
    std::string line = "unknown key '" + key + "' in " + (at.where.empty() ? "/" : at.where);
    // Close enough to be a typo: at most a third of the key's letters (1 to 3 edits).
    const size_t limit = std::clamp<size_t>(key.size() / 3, 1, 3);
    const std::string* best = nullptr;
    size_t bestDistance = limit + 1;
    for (const std::string& k : known)
        if (const size_t d = editDistance(key, k); d < bestDistance) {
            best = &k;
            bestDistance = d;
        }
    if (best) line += " (did you mean '" + *best + "'?)";
    return line;
}

util::Status readExtras(const Json& value, const JsonPlace& at, std::string* extras) {
    if (!value.is_object())
        return jsonError(ErrorKind::Format, at, std::string("extras: expected an object, got ") + jsonTypeName(value));
    *extras = value.dump();
    return util::okStatus();
}

void writeExtras(Json& obj, const std::string& extras) {
    if (!extras.empty()) obj["extras"] = Json::parse(extras);
}

util::Status readProperties(const Json& obj, EntityKind kind, void* entity, const JsonPlace& at,
                            const std::set<std::string>& structural, std::string* extras,
                            std::vector<std::string>& problems) {
    if (!obj.is_object())
        return jsonError(ErrorKind::Format, at,
                         std::string("expected a ") + entityKindName(kind) + " object, got " + jsonTypeName(obj));
    // Unknown keys first: a misspelt required key then shows its suggestion next to the error.
    std::vector<std::string> known;
    for (const PropertyInfo& info : properties(kind)) known.push_back(info.name);
    known.insert(known.end(), structural.begin(), structural.end());
    known.push_back("extras");
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            problems.push_back(unknownKeyProblem(it.key(), at, known));
    if (auto it = obj.find("extras"); it != obj.end())
        if (auto s = readExtras(*it, at.child("extras"), extras); !s) return s;
    for (const PropertyInfo& info : properties(kind)) {
        auto it = obj.find(info.name);
        if (it == obj.end()) {
            if (info.required)
                return jsonError(ErrorKind::Invalid, at,
                                 std::string(entityKindName(kind)) + " is missing required key '" + info.name + "'");
            continue;
        }
        // An option of a named kind that no one registered (a BRDF no plugin provides): listed
        // with the entity's name, and the entity keeps its default (the load fails anyway).
        if (info.type == PropertyType::Enum && !info.enumNoun.empty() && it->is_string() &&
            std::find(info.enumOptions.begin(), info.enumOptions.end(), it->get<std::string>()) == info.enumOptions.end()) {
            const auto name = obj.find("name");
            const std::string who = std::string(entityKindName(kind)) +
                                    (name != obj.end() && name->is_string() ? " '" + name->get<std::string>() + "'" : "");
            problems.push_back(who + " (" + at.child(info.name).where + "): " +
                               unknownOptionMessage(info, it->get<std::string>()));
            continue;
        }
        auto value = valueFromJson(*it, info, at.child(info.name));
        if (!value) return value.error();
        info.set(entity, *value);
    }
    // A key of the kind that this entity's type does not use (a cone on a rect light) would stay in
    // the model unseen and vanish at the next save (writeProperties writes applicable ones only):
    // listed like an unknown key. Checked once all keys are read, "type" included.
    for (const PropertyInfo& info : properties(kind))
        if (obj.contains(info.name) && !propertyApplies(info, entity)) {
            std::string what = entityKindName(kind);
            if (const PropertyInfo* type = findProperty(kind, "type"))
                what = std::get<std::string>(type->get(entity)) + " " + what;
            problems.push_back("key '" + info.name + "' in " + (at.where.empty() ? "/" : at.where) +
                               " does not apply to a " + what);
        }
    return util::okStatus();
}

void writeProperties(Json& obj, EntityKind kind, const void* entity) {
    for (const PropertyInfo& info : properties(kind))
        if (propertyApplies(info, entity) &&
            !(info.omitWhenDefault && info.get(entity) == info.defaultValue))
            obj[info.name] = valueToJson(info.get(entity));
}

} // namespace wavelit::scene
