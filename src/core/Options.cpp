#include <shadowlab/Options.h>
#include <shadowlab/Text.h>

#include <cmath>

namespace shadowlab {

namespace {
const char* kindName(OptionKind kind) {
    switch (kind) {
    case OptionKind::Number: return "number";
    case OptionKind::Integer: return "integer";
    case OptionKind::Boolean: return "boolean";
    case OptionKind::Choice: return "string";
    case OptionKind::Text: return "string";
    }
    return "?";
}
} // namespace

const OptionField* OptionTable::find(std::string_view key) const {
    for (const OptionField& f : fields)
        if (f.key == key) return &f;
    return nullptr;
}

std::string OptionTable::valueText(const OptionField& field, const std::any& options) const {
    if (field.kind == OptionKind::Text) {
        std::string out = "\"";
        for (char c : field.getText(options)) {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
        return out + "\"";
    }
    const double v = field.get(options);
    switch (field.kind) {
    case OptionKind::Boolean: return v != 0.0 ? "true" : "false";
    case OptionKind::Choice: {
        const auto i = static_cast<std::size_t>(v);
        return i < field.choices.size() ? "\"" + field.choices[i] + "\"" : "?";
    }
    case OptionKind::Integer: return std::to_string(static_cast<long long>(std::llround(v)));
    case OptionKind::Number: return text::numberText(v);
    case OptionKind::Text: break;
    }
    return "?";
}

std::string OptionTable::rangeText(const OptionField& field) {
    switch (field.kind) {
    case OptionKind::Boolean: return "true, false";
    case OptionKind::Choice: {
        std::string out;
        for (const std::string& c : field.choices) out += (out.empty() ? "\"" : ", \"") + c + "\"";
        for (const ChoiceAlias& a : field.aliases) out += ", \"" + a.name + "\" (" + a.doc + ")";
        return out;
    }
    case OptionKind::Integer:
    case OptionKind::Number: return text::numberText(field.minimum) + ".." + text::numberText(field.maximum);
    case OptionKind::Text: return field.choices.empty() ? std::string("text") : field.choices[0];
    }
    return "?";
}

std::string OptionTable::markdown() const {
    std::string out = "| key | type | default | allowed | unit | meaning |\n|---|---|---|---|---|---|\n";
    for (const OptionField& f : fields)
        out += "| `" + f.key + "` | " + kindName(f.kind) + " | `" + defaultText(f) + "` | " + rangeText(f) + " | " +
               (f.unit.empty() ? "-" : f.unit) + " | " + f.doc + " |\n";
    return out;
}

} // namespace shadowlab
