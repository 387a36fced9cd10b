#pragma once
// Reading a scene file's JSON (docs/scene-format.md): each value is read
// through a Reader that knows its JSON path, so any error names the file
// (or the `--set` flag), the path and what was expected, and unknown keys
// are errors. Also the keyframes that camera and light paths share.
// Private to the scene loader; the parts of a scene are in SceneParts.h.
#include "scene/Overrides.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::scenefile {

// --- Reading values with their JSON path ------------------------------------

struct ParseContext {
    std::string source;  // file name for messages
    std::filesystem::path baseDir;
    std::vector<overrides::Override> overrides;
    std::vector<std::string> notes;  // what was chosen for the scene (a glTF include's far plane), Scene::notes

    /// Throws shadowlab::Error naming the source, `path` and `message`, or
    /// the `--set` flag whose value the path lies in.
    [[noreturn]] void fail(const std::string& path, const std::string& message) const;
    /// The same as UnsupportedError (Error.h): a combination the light's technique cannot draw.
    [[noreturn]] void failUnsupported(const std::string& path, const std::string& message) const;
};

class Reader {
public:
    Reader(const ParseContext& ctx, const nlohmann::json& value, std::string path)
        : ctx_(ctx), value_(value), path_(std::move(path)) {}

    const nlohmann::json& value() const { return value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const { ctx_.fail(path_, message); }
    [[noreturn]] void failUnsupported(const std::string& message) const { ctx_.failUnsupported(path_, message); }

    Reader child(const std::string& key) const {
        return Reader(ctx_, value_.at(key), path_.empty() ? key : path_ + "." + key);
    }
    Reader element(std::size_t i) const { return Reader(ctx_, value_.at(i), path_ + "[" + std::to_string(i) + "]"); }

    void requireObject() const { if (!value_.is_object()) fail(std::string("expected an object, got ") + overrides::typeName(value_)); }
    void requireArray() const { if (!value_.is_array()) fail(std::string("expected an array, got ") + overrides::typeName(value_)); }

    // Errors for keys that are not in `known`.
    void checkKeys(std::initializer_list<const char*> known) const { checkKeys(std::vector<const char*>(known)); }
    void checkKeys(const std::vector<const char*>& known) const;
    bool has(const std::string& key) const { return value_.contains(key); }

    float number() const { return static_cast<float>(real()); }
    /// The same checks as number() (finite, within a float's range), kept in double.
    double real() const;
    int integer() const;
    bool boolean() const;
    std::string string() const;
    glm::vec3 vec3() const;

    // Optional members with defaults and checks.
    float number(const std::string& key, float def) const { return has(key) ? child(key).number() : def; }
    float positive(const std::string& key, float def) const;
    float nonNegative(const std::string& key, float def) const;
    int integer(const std::string& key, int def, int minimum, int maximum) const;
    glm::vec3 vec3(const std::string& key, glm::vec3 def) const { return has(key) ? child(key).vec3() : def; }
    glm::vec3 color(const std::string& key, glm::vec3 def) const;
    glm::vec3 direction(const std::string& key, glm::vec3 def) const;
    std::string string(const std::string& key, const std::string& def) const { return has(key) ? child(key).string() : def; }
    bool boolean(const std::string& key, bool def) const { return has(key) ? child(key).boolean() : def; }

    const ParseContext& context() const { return ctx_; }

    static std::string fmt(double v);

private:
    const ParseContext& ctx_;
    const nlohmann::json& value_;
    std::string path_;
};

// --- Keyframes --------------------------------------------------------------

// Keyframes, shared by `lights[i].path` and `camera.path`: `times` (seconds,
// at least one, strictly increasing) and, under `key`, one [x, y, z] per
// time, each called `what` in messages.
std::vector<double> readKeyTimes(const Reader& r);
std::vector<glm::vec3> readKeyPoints(const Reader& r, const std::string& key, const std::string& what, std::size_t count);

} // namespace shadowlab::scenefile
