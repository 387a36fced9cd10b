// The `lights` of a scene file: each light's type, colour, placement and
// cone, its `path` (how a spot or point light moves) and its `shadow` block,
// the technique and every technique's options read through its table.
#include "scene/SceneParts.h"

#include "techniques/Catalog.h"

#include <shadowlab/Techniques.h>

#include <algorithm>
#include <any>
#include <cmath>

namespace shadowlab::scenefile {

namespace {

std::string techniqueList() {
    std::string list;
    for (const TechniqueInfo& t : techniques()) list += (list.empty() ? "" : ", ") + t.name;
    return list;
}

// One technique's block, `lights[i].shadow.<name>`, read through its options
// table: every key known, every value of its kind and within its range.
std::any readOptions(const Reader& r, const OptionTable& table) {
    r.requireObject();
    if (table.fields.empty() && !r.value().empty())
        r.child(r.value().begin().key()).fail("unknown key (technique '" + table.block + "' has no options)");
    std::vector<const char*> keys;
    for (const OptionField& f : table.fields) keys.push_back(f.key.c_str());
    r.checkKeys(keys);
    std::any options = table.makeDefault();
    for (const OptionField& f : table.fields) {
        if (!r.has(f.key)) continue;
        const Reader v = r.child(f.key);
        const std::string allowed = OptionTable::rangeText(f);
        switch (f.kind) {
        case OptionKind::Number: {
            // Compared as the float the member stores, so that the range's own ends (0.1) are allowed.
            const float x = v.number();
            if (x < static_cast<float>(f.minimum) || x > static_cast<float>(f.maximum)) v.fail("expected a number in " + allowed + ", got " + Reader::fmt(static_cast<float>(x)));
            f.set(options, x);
            break;
        }
        case OptionKind::Integer: {
            const int x = v.integer();
            if (x < f.minimum || x > f.maximum) v.fail("expected an integer in " + allowed + ", got " + std::to_string(x));
            f.set(options, x);
            break;
        }
        case OptionKind::Boolean: f.set(options, v.boolean() ? 1.0 : 0.0); break;
        case OptionKind::Choice: {
            std::string name = v.string();
            // Another name (the lectures' "pcf"): its value, and what it implies where the block is silent.
            const auto alias = std::find_if(f.aliases.begin(), f.aliases.end(), [&](const ChoiceAlias& a) { return a.name == name; });
            if (alias != f.aliases.end()) name = alias->means;
            const auto it = std::find(f.choices.begin(), f.choices.end(), name);
            if (it == f.choices.end()) v.fail("expected one of " + allowed + ", got \"" + name + "\"");
            f.set(options, static_cast<double>(it - f.choices.begin()));
            if (alias != f.aliases.end())
                for (const auto& [key, value] : alias->implies)
                    if (const OptionField* other = table.find(key); other && !r.has(key)) other->set(options, value);
            break;
        }
        case OptionKind::Text: f.setText(options, v.string()); break;
        }
    }
    return options;
}

void readShadow(const Reader& r, ShadowSettings& shadow, const Light& light) {
    std::vector<const char*> keys{"technique"};
    const std::vector<TechniqueInfo> all = techniques();
    for (const TechniqueInfo& t : all) keys.push_back(t.name.c_str());
    r.checkKeys(keys);
    if (r.has("technique")) {
        const Reader t = r.child("technique");
        shadow.technique = t.string();
        if (!findTechnique(shadow.technique))
            t.fail("unknown technique '" + shadow.technique + "' (expected one of: " + techniqueList() + ")");
    }
    // Every block is read and checked, the chosen technique's or not, so a
    // scene can carry several and switch between them.
    for (const TechniqueInfo& t : all) {
        if (!r.has(t.name)) continue;
        const Reader block = r.child(t.name);
        std::any options = readOptions(block, *t.options);
        // Options that are others' defaults (map's preset), under the keys the block wrote.
        if (const TechniqueKind* kind = findTechniqueKind(t.name); kind && kind->resolve) {
            std::vector<std::string> written;
            for (const auto& item : block.value().items()) written.push_back(item.key());
            kind->resolve(options, written, light);
        }
        shadow.options[t.name] = std::move(options);
    }
    // Whether the technique can shadow this light may depend on its options
    // (a preset), so this comes after the blocks.
    const std::string reason = unsupportedReason(shadow.technique, light);
    if (reason.empty()) return;
    // The option the reason names ("map: cascadeSplits ...") is at fault
    // when the scene sets it, not the technique's name.
    const TechniqueInfo* info = findTechnique(shadow.technique);
    const std::string prefix = shadow.technique + ": ";
    if (info && info->options && reason.rfind(prefix, 0) == 0 && r.has(shadow.technique)) {
        const Reader block = r.child(shadow.technique);
        const std::string named = reason.substr(prefix.size());
        for (const OptionField& f : info->options->fields) {
            const bool names = named.rfind(f.key, 0) == 0 && (named.size() == f.key.size() || named[f.key.size()] == ' ' || named[f.key.size()] == ':');
            if (names && block.has(f.key)) block.child(f.key).failUnsupported(reason);
        }
    }
    (r.has("technique") ? r.child("technique") : r).failUnsupported(reason);
}

// `lights[i].path`: how a spot or point light moves (LightPath in Scene.h).
LightPath readPath(const Reader& r, const glm::vec3& base) {
    r.requireObject();
    if (!r.has("type")) r.fail("missing key 'type' (sine or keyframes)");
    const std::string type = r.child("type").string();
    LightPath path;
    // Every position the path reaches must be a finite float, as a static light's is.
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (type == "sine") {
        r.checkKeys({"type", "amplitude", "angularFrequency", "phase"});
        path.type = LightPath::Type::Sine;
        path.amplitude = r.vec3("amplitude", path.amplitude);
        if (!finite(base + path.amplitude) || !finite(base - path.amplitude))
            r.child("amplitude").fail("position + amplitude overflows a float");
        if (r.has("angularFrequency")) {
            const Reader w = r.child("angularFrequency");
            path.angularFrequency = w.real();
            if (path.angularFrequency < 0.0)
                w.fail("expected radians per second >= 0, got " + Reader::fmt(path.angularFrequency) +
                       " (reverse the motion with a negative amplitude or a phase)");
        }
        if (r.has("phase")) path.phase = r.child("phase").real();
        return path;
    }
    if (type == "keyframes") {
        r.checkKeys({"type", "times", "positions", "loop"});
        path.type = LightPath::Type::Keyframes;
        path.times = readKeyTimes(r);
        path.positions = readKeyPoints(r, "positions", "position", path.times.size());
        path.loop = r.boolean("loop", path.loop);
        return path;
    }
    r.child("type").fail("unknown path type '" + type + "' (expected sine or keyframes)");
}

} // namespace

Light readLight(const Reader& r) {
    r.checkKeys({"name", "type", "color", "intensity", "position", "direction", "range", "innerCone", "outerCone",
                 "size", "projector", "path", "shadow"});
    Light light;
    if (!r.has("type")) r.fail("missing key 'type' (directional, spot or point)");
    const std::string type = r.child("type").string();
    if (type == "directional") light.type = LightType::Directional;
    else if (type == "spot") light.type = LightType::Spot;
    else if (type == "point") light.type = LightType::Point;
    else r.child("type").fail("expected directional, spot or point, got '" + type + "'");
    light.name = r.string("name", type);
    light.color = r.color("color", light.color);
    light.intensity = r.nonNegative("intensity", light.intensity);
    const bool positional = light.type != LightType::Directional;
    if (positional && !r.has("position")) r.fail("missing key 'position' (a " + type + " light needs one)");
    if (!positional && r.has("position")) r.child("position").fail("a directional light has no position (use direction)");
    light.position = r.vec3("position", light.position);
    if (light.type == LightType::Point && r.has("direction")) r.child("direction").fail("a point light has no direction");
    light.direction = r.direction("direction", light.direction);
    light.range = r.nonNegative("range", light.range);
    if (light.type != LightType::Spot && (r.has("innerCone") || r.has("outerCone")))
        r.child(r.has("innerCone") ? "innerCone" : "outerCone").fail("only spot lights have cone angles");
    light.innerConeDeg = r.nonNegative("innerCone", light.innerConeDeg);
    light.outerConeDeg = r.positive("outerCone", light.outerConeDeg);
    if (light.outerConeDeg >= 90.0f) r.child("outerCone").fail("expected degrees in (0, 90), got " + Reader::fmt(light.outerConeDeg));
    if (light.innerConeDeg > light.outerConeDeg)
        (r.has("innerCone") ? r.child("innerCone") : r).fail("expected innerCone <= outerCone (" + Reader::fmt(light.outerConeDeg) + ")");
    light.size = r.nonNegative("size", light.size);
    if (light.type == LightType::Directional && light.size >= 90.0f)
        r.child("size").fail("expected an angular diameter in degrees < 90, got " + Reader::fmt(light.size));
    if (r.has("projector") && light.type != LightType::Spot) r.child("projector").fail("only spot lights project an image");
    if (r.has("path")) {
        if (!positional) r.child("path").fail("a directional light has no position to move (only spot and point lights have a path)");
        light.path = readPath(r.child("path"), light.position);
    }
    if (r.has("shadow")) readShadow(r.child("shadow"), light.shadow, light);
    return light;
}

} // namespace shadowlab::scenefile
