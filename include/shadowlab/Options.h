#pragma once
/// @file Options.h
/// Options as data. Every technique's options struct comes with an
/// OptionTable: one row per field with its JSON key, unit, default, allowed
/// range or names, and a one-line doc. The one table drives the scene-file
/// parser (`lights[i].shadow.<technique>.<key>`, errors with the JSON path),
/// `--set` and `bench --vary` (which use the same JSON paths), the
/// scene-format doc's tables (a test compares them) and the viewer's controls.
#include <shadowlab/Export.h>
#include <any>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

enum class OptionKind {
    Number,  ///< float member; JSON number within [minimum, maximum]
    Integer, ///< int member; JSON integer within [minimum, maximum]
    Boolean, ///< bool member; JSON true/false
    Choice,  ///< enum member (0, 1, 2 ...); JSON string, one of `choices`
    Text,    ///< std::string member; JSON string (e.g. a comma-separated list of node names)
};

/// Another name for one of a Choice's values (the lectures' "pcf" for the
/// grid filter), with the values it implies for other fields of the block
/// (kernel 8) unless the block writes them.
struct ChoiceAlias {
    std::string name;                                     ///< the other name, accepted where the choice is written
    std::string means;                                    ///< the choice it stands for (one of OptionField::choices)
    std::vector<std::pair<std::string, double>> implies;  ///< other fields' values (Choice: index), where not written
    std::string doc;                                      ///< one clause: what it is ("the lectures' PCF: ...")
};

struct OptionField {
    std::string key;                  ///< JSON key inside the technique's block
    OptionKind kind = OptionKind::Number;
    std::string unit;                 ///< e.g. "texels", "degrees"; empty for none
    double minimum = 0.0;             ///< Number, Integer: smallest allowed value
    double maximum = 0.0;             ///< Number, Integer: largest allowed value
    std::vector<std::string> choices; ///< Choice: the names, in enum order; Text: one line saying what it may hold
    std::string doc;                  ///< one line
    std::vector<ChoiceAlias> aliases; ///< Choice: other names accepted for its values
    /// The member's value as a number (Choice: its index; Boolean: 0 or 1).
    std::function<double(const std::any&)> get;
    /// Sets the member from a number that is valid for the field.
    std::function<void(std::any&, double)> set;
    /// Text: the member's value, and setting it.
    std::function<std::string(const std::any&)> getText;
    std::function<void(std::any&, const std::string&)> setText;
};

/// The fields of one options struct. Build it with OptionTableFor<T>.
class SHADOWLAB_API OptionTable {
public:
    std::string block;                ///< the JSON block's key: the technique's name
    std::vector<OptionField> fields;
    std::function<std::any()> makeDefault; ///< a default-constructed options struct

    const OptionField* find(std::string_view key) const;
    /// The field's value in `options` as it is written in JSON: `2048`,
    /// `0.5`, `true`, `"pcf"`.
    std::string valueText(const OptionField& field, const std::any& options) const;
    /// valueText of the default.
    std::string defaultText(const OptionField& field) const { return valueText(field, makeDefault()); }
    /// The allowed values as the docs write them: `64..16384`, `0..1`,
    /// `true, false`, `"none", "pcf"`.
    static std::string rangeText(const OptionField& field);
    /// The Markdown table of the fields (key, type, default, allowed, unit,
    /// meaning) that docs/scene-format.md carries for this block.
    std::string markdown() const;
};

/// Builds an OptionTable for options struct T from pointers to its members.
template <class T>
class OptionTableFor {
public:
    explicit OptionTableFor(std::string block) {
        table_.block = std::move(block);
        table_.makeDefault = [] { return std::any(T{}); };
    }
    OptionTableFor& number(float T::*member, std::string key, double minimum, double maximum, std::string unit, std::string doc) {
        add(key, OptionKind::Number, unit, minimum, maximum, {}, doc,
            [member](const T& t) { return static_cast<double>(t.*member); },
            [member](T& t, double v) { t.*member = static_cast<float>(v); });
        return *this;
    }
    OptionTableFor& integer(int T::*member, std::string key, int minimum, int maximum, std::string unit, std::string doc) {
        add(key, OptionKind::Integer, unit, minimum, maximum, {}, doc,
            [member](const T& t) { return static_cast<double>(t.*member); },
            [member](T& t, double v) { t.*member = static_cast<int>(v); });
        return *this;
    }
    OptionTableFor& boolean(bool T::*member, std::string key, std::string doc) {
        std::string noUnit;
        add(key, OptionKind::Boolean, noUnit, 0, 1, {}, doc, [member](const T& t) { return t.*member ? 1.0 : 0.0; },
            [member](T& t, double v) { t.*member = v != 0.0; });
        return *this;
    }
    template <class E>
    OptionTableFor& choice(E T::*member, std::string key, std::vector<std::string> names, std::string doc) {
        const double last = static_cast<double>(names.size()) - 1.0;
        std::string noUnit;
        add(key, OptionKind::Choice, noUnit, 0, last, std::move(names), doc,
            [member](const T& t) { return static_cast<double>(static_cast<int>(t.*member)); },
            [member](T& t, double v) { t.*member = static_cast<E>(static_cast<int>(v)); });
        return *this;
    }
    /// `name` accepted for the last field's (a Choice's) value `means`,
    /// setting `implies` (other fields by key) where the block does not write them.
    OptionTableFor& alias(std::string name, std::string means, std::vector<std::pair<std::string, double>> implies, std::string doc) {
        table_.fields.back().aliases.push_back({std::move(name), std::move(means), std::move(implies), std::move(doc)});
        return *this;
    }
    OptionTableFor& text(std::string T::*member, std::string key, std::string allowed, std::string doc) {
        std::string noUnit;
        add(key, OptionKind::Text, noUnit, 0, 0, {std::move(allowed)}, doc, [](const T&) { return 0.0; }, [](T&, double) {});
        OptionField& f = table_.fields.back();
        f.getText = [member](const std::any& a) { return std::any_cast<const T&>(a).*member; };
        f.setText = [member](std::any& a, const std::string& v) { std::any_cast<T&>(a).*member = v; };
        return *this;
    }
    /// A text option naming scene nodes, comma-separated (which nodes a
    /// technique treats as its casters or receivers; empty: the technique's own choice).
    OptionTableFor& nodeNames(std::string T::*member, std::string key, std::string doc) {
        return text(member, std::move(key), "node names, comma-separated", std::move(doc));
    }
    OptionTable build() { return std::move(table_); }

private:
    template <class Get, class Set>
    void add(std::string& key, OptionKind kind, std::string& unit, double minimum, double maximum, std::vector<std::string> choices,
             std::string& doc, Get get, Set set) {
        OptionField f;
        f.key = std::move(key);
        f.kind = kind;
        f.unit = std::move(unit);
        f.minimum = minimum;
        f.maximum = maximum;
        f.choices = std::move(choices);
        f.doc = std::move(doc);
        f.get = [get](const std::any& a) { return get(std::any_cast<const T&>(a)); };
        f.set = [set](std::any& a, double v) { set(std::any_cast<T&>(a), v); };
        table_.fields.push_back(std::move(f));
    }
    OptionTable table_;
};

} // namespace shadowlab
