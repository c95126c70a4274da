#include "render/frame/Field.hpp"

#include <charconv>
#include <cmath>

namespace speculum::render {

namespace {

bool isInteger(double v) {
    return std::isfinite(v) && v == std::floor(v);
}

// The unit as a word after a range in a message: "0.001..1e+09 seconds", "(0, 90] degrees".
std::string unitWords(const FieldSpec& spec) {
    if (spec.unit == "°")
        return " degrees";
    if (spec.unit == " s")
        return " seconds";
    return {};
}

bool symmetric(const FieldSpec& spec) {
    return spec.min == -spec.max && std::isfinite(spec.max);
}

// One number against the spec's range: "must be in 0..1, got 2", or nothing.
std::optional<std::string> numberProblem(const FieldSpec& spec, double v) {
    const std::string got = ", got " + shortestNumber(v);
    if (!std::isfinite(v))
        return "expected a finite number";
    double a = v;
    if (spec.rule == FieldRule::Magnitude) {
        if (v == 0.0)
            return std::string("must be non-zero");
        a = std::abs(v);
    }
    const bool below = a < spec.min || (spec.minOpen && a == spec.min);
    const bool above = a > spec.max || (spec.maxOpen && a == spec.max);
    if (!below && !above)
        return std::nullopt;
    if (symmetric(spec))
        return "must be within " + rangeText(spec) + got;
    if (spec.minOpen && spec.maxOpen)
        return "must be between " + shortestNumber(spec.min) + " and " + shortestNumber(spec.max) +
               unitWords(spec) + " (exclusive)" + got;
    // "Not negative" where the top of the range is no real limit (an intensity up to 1e9); a bounded range
    // is named whole ("must be in 0..1").
    if (below && spec.min == 0.0 && !spec.minOpen && spec.max >= 1e9)
        return "must not be negative" + got;
    if (below && v <= 0.0 && (spec.min > 0.0 || spec.minOpen) && spec.rule != FieldRule::Magnitude)
        return "must be greater than 0" + got;
    if (above && spec.min == 0.0 && !spec.minOpen && spec.max >= 1e9)
        return "must be at most " + shortestNumber(spec.max) + got;
    const std::string size = spec.rule == FieldRule::Magnitude ? " in size" : "";
    return "must be in " + rangeText(spec) + unitWords(spec) + size + got;
}

std::optional<std::string> integerProblem(const FieldSpec& spec, int v) {
    const std::string range = shortestNumber(spec.min) + ".." + shortestNumber(spec.max);
    const std::string got = ", got " + std::to_string(v);
    const bool inRange = v >= spec.min && v <= spec.max;
    if (spec.rule == FieldRule::PowerOfTwo && !(inRange && v > 0 && (v & (v - 1)) == 0))
        return "must be a power of two in " + range + got;
    if (spec.rule == FieldRule::Odd && !(inRange && v % 2 != 0))
        return "must be an odd " + std::string(spec.noun.empty() ? "number" : spec.noun) + " in " + range +
               got;
    return numberProblem(spec, v);
}

template <int N>
std::optional<std::string> vectorProblem(const FieldSpec& spec, const glm::vec<N, double>& v) {
    for (int i = 0; i < N; ++i) {
        if (spec.type == FieldType::Color && !(v[i] >= 0.0 && v[i] <= 1.0))
            return "colour components must be in 0..1 (linear RGB), got " + shortestNumber(v[i]);
        if (auto problem = numberProblem(spec, v[i])) {
            const std::string subject = spec.noun.empty() ? "components" : std::string(spec.noun);
            return subject + " " + *problem;
        }
    }
    return std::nullopt;
}

} // namespace

std::string shortestNumber(double value) {
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
    return error == std::errc() ? std::string(text, end) : std::string("?");
}

std::string rangeText(const FieldSpec& spec) {
    if (symmetric(spec))
        return "±" + shortestNumber(spec.max);
    if (spec.minOpen || spec.maxOpen)
        return (spec.minOpen ? "(" : "[") + shortestNumber(spec.min) + ", " + shortestNumber(spec.max) +
               (spec.maxOpen ? ")" : "]");
    return shortestNumber(spec.min) + ".." + shortestNumber(spec.max);
}

std::optional<std::string> fieldProblem(const FieldSpec& spec, const FieldValue& value) {
    switch (spec.type) {
    case FieldType::Integer:
        if (const int* i = std::get_if<int>(&value))
            return integerProblem(spec, *i);
        return std::string("expected an integer");
    case FieldType::Number:
        if (const double* d = std::get_if<double>(&value))
            return numberProblem(spec, *d);
        if (const int* i = std::get_if<int>(&value))
            return numberProblem(spec, *i);
        return std::string("expected a number");
    case FieldType::Vector2:
        if (const auto* v = std::get_if<glm::dvec2>(&value))
            return vectorProblem<2>(spec, *v);
        return std::string("expected 2 numbers");
    case FieldType::Vector3:
    case FieldType::Color:
        if (const auto* v = std::get_if<glm::dvec3>(&value))
            return vectorProblem<3>(spec, *v);
        return std::string("expected 3 numbers");
    case FieldType::Choice:
        if (const int* i = std::get_if<int>(&value); i && *i >= 0 && std::size_t(*i) < spec.choices.size())
            return std::nullopt;
        return "unknown " + std::string(spec.noun) + " (expected " + names::choices(spec.choices) + ")";
    case FieldType::Bool:
        if (std::holds_alternative<bool>(value))
            return std::nullopt;
        return std::string("expected true or false");
    case FieldType::Path:
        if (const auto* s = std::get_if<std::string>(&value))
            return s->empty() ? std::optional<std::string>("expected a file path, got an empty string")
                              : std::nullopt;
        return std::string("expected a string");
    case FieldType::Text:
        if (std::holds_alternative<std::string>(value))
            return std::nullopt;
        return std::string("expected a string");
    case FieldType::WrapPair:
    case FieldType::Object:
        break;
    }
    return std::nullopt;
}

std::string fieldValueText(const FieldSpec& spec, const FieldValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) {
        if (spec.choices.size() == 2) // spelled by name for bench results: "full", "simplified"
            return std::string(spec.choices[*b ? 1 : 0].file);
        return *b ? "true" : "false";
    }
    if (const int* i = std::get_if<int>(&value)) {
        if (spec.type == FieldType::Choice)
            return *i >= 0 && std::size_t(*i) < spec.choices.size()
                       ? std::string(spec.choices[std::size_t(*i)].file)
                       : std::string("?");
        return std::to_string(*i);
    }
    if (const double* d = std::get_if<double>(&value))
        return shortestNumber(*d);
    if (const auto* v2 = std::get_if<glm::dvec2>(&value))
        return shortestNumber(v2->x) + " " + shortestNumber(v2->y);
    if (const auto* v3 = std::get_if<glm::dvec3>(&value))
        return shortestNumber(v3->x) + " " + shortestNumber(v3->y) + " " + shortestNumber(v3->z);
    return std::get<std::string>(value);
}

std::variant<FieldValue, std::string> parseFieldValue(const FieldSpec& spec, std::string_view text) {
    const auto number = [&](double& out) {
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
        return error == std::errc() && end == text.data() + text.size();
    };
    switch (spec.type) {
    case FieldType::Bool:
        if (spec.choices.size() == 2) {
            if (text == spec.choices[0].file || text == spec.choices[1].file)
                return FieldValue(text == spec.choices[1].file);
            return "expected " + std::string(spec.choices[0].file) + " or " +
                   std::string(spec.choices[1].file);
        }
        if (text == "true" || text == "false")
            return FieldValue(text == "true");
        return std::string("expected true or false");
    case FieldType::Integer: {
        double d = 0.0;
        if (number(d) && isInteger(d) && std::abs(d) <= 1e9)
            return FieldValue(static_cast<int>(d));
        return std::string("expected an integer");
    }
    case FieldType::Number: {
        double d = 0.0;
        if (number(d))
            return FieldValue(d);
        return std::string("expected a number");
    }
    case FieldType::Choice:
        if (auto index = names::fromFileName<int>(spec.choices, text))
            return FieldValue(*index);
        return "unknown " + std::string(spec.noun) + " (expected " + names::choices(spec.choices) + ")";
    case FieldType::Path:
    case FieldType::Text:
        return FieldValue(std::string(text));
    default:
        break;
    }
    return std::string("cannot be given as text");
}

} // namespace speculum::render
