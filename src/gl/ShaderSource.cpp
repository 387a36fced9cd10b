#include "gl/ShaderSource.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>

namespace shadowlab::gl {

namespace {

struct AddedFiles {
    std::mutex mutex;
    std::map<std::string, std::string, std::less<>> files;  // nodes are stable: views stay valid
};
AddedFiles& addedFiles() {
    static AddedFiles added;
    return added;
}

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            if (start < text.size()) lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// Returns the quoted name if `line` is `#include "name"`.
std::optional<std::string_view> includeTarget(std::string_view line) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line.compare(first, 8, "#include") != 0) return std::nullopt;
    const auto open = line.find('"', first + 8);
    const auto close = open == std::string_view::npos ? open : line.find('"', open + 1);
    if (close == std::string_view::npos) return std::nullopt;
    return line.substr(open + 1, close - open - 1);
}

struct Assembly {
    const IncludeAliases& aliases;
    std::optional<std::string_view> inlineText; // the top file's text when given inline
};

void appendFile(std::string_view requested, AssembledSource& out, std::vector<std::string>& stack, const Assembly& how) {
    std::string_view name = requested;
    if (!requested.empty() && requested.front() == '@') {
        // "@slot?" is an optional slot: nothing when the variant leaves it empty.
        const bool optional = requested.back() == '?';
        const std::string_view slot = optional ? requested.substr(0, requested.size() - 1) : requested;
        const auto it = std::find_if(how.aliases.begin(), how.aliases.end(), [&](const auto& a) { return a.first == slot; });
        if (it == how.aliases.end()) {
            if (optional) return;
            throw Error(stack.back() + ": #include \"" + std::string(requested) + "\": the variant fills no such slot");
        }
        name = it->second;
    }
    const auto text = stack.empty() && how.inlineText ? how.inlineText : shaderFile(name);
    if (!text) {
        throw Error(stack.empty() ? "shader " + std::string(name) + ": no such embedded shader file"
                                  : stack.back() + ": #include \"" + std::string(name) + "\": no such embedded shader file");
    }
    if (std::find(stack.begin(), stack.end(), name) != stack.end())
        throw Error(stack.back() + ": #include \"" + std::string(name) + "\" forms a cycle");
    stack.emplace_back(name);
    const int index = static_cast<int>(out.files.size());
    out.files.emplace_back(name);
    out.text += "#line 1 " + std::to_string(index) + "\n";
    int lineNo = 0;
    for (std::string_view line : splitLines(*text)) {
        ++lineNo;
        if (auto target = includeTarget(line)) {
            appendFile(*target, out, stack, how);
            out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
        } else {
            out.text.append(line);
            out.text += '\n';
        }
    }
    stack.pop_back();
}

} // namespace

void addShaderFile(const std::string& name, std::string text) {
    AddedFiles& added = addedFiles();
    std::lock_guard lock(added.mutex);
    if (embeddedShader(name) || added.files.count(name)) throw Error("addShaderFile: '" + name + "' already exists");
    added.files.emplace(name, std::move(text));
}

std::optional<std::string_view> shaderFile(std::string_view name) {
    AddedFiles& added = addedFiles();
    {
        std::lock_guard lock(added.mutex);
        const auto it = added.files.find(name);
        if (it != added.files.end()) return std::string_view(it->second);
    }
    return embeddedShader(name);
}

AssembledSource assembleShader(std::string_view fileName, std::string_view preamble, const IncludeAliases& aliases,
                               std::optional<std::string_view> inlineText) {
    AssembledSource out;
    out.files.emplace_back("<variant preamble>");
    out.text = "#version 450 core\n";
    if (inlineText) out.inlineText = std::string(*inlineText);
    out.text.append(preamble);
    if (!preamble.empty() && preamble.back() != '\n') out.text += '\n';
    // How this GL flavour spells what GLSL ES 3.00 spells otherwise, the
    // only place it is written: a sampler's or block's unit is given in the
    // shader (SL_BINDING(unit) before `uniform`).
    out.text += "#define SL_BINDING(unit) layout(binding = unit)\n";
    std::vector<std::string> stack;
    appendFile(fileName, out, stack, Assembly{aliases, inlineText});
    return out;
}

std::string describeShaderLog(std::string_view log, const AssembledSource& source) {
    static const std::regex mesa(R"(^(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::string out;
    for (std::string_view lineView : splitLines(log)) {
        const std::string line(lineView);
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::smatch m;
        if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia)) {
            const std::size_t fileIndex = std::stoul(m[1].str());
            const int lineNo = std::stoi(m[2].str());
            std::string name = fileIndex < source.files.size() ? source.files[fileIndex] : "<unknown>";
            std::string text;
            if (fileIndex > 0 && fileIndex < source.files.size()) {
                const auto file = fileIndex == 1 && !source.inlineText.empty() ? std::optional<std::string_view>(source.inlineText)
                                                                                 : shaderFile(name);
                if (file) {
                    auto lines = splitLines(*file);
                    if (lineNo >= 1 && lineNo <= static_cast<int>(lines.size())) {
                        auto l = lines[lineNo - 1];
                        const auto first = l.find_first_not_of(" \t");
                        text = first == std::string_view::npos ? "" : std::string(l.substr(first));
                    }
                }
            }
            if (!out.empty()) out += "; ";
            out += name + ":" + std::to_string(lineNo) + ": " + m[3].str();
            if (!text.empty()) out += " | " + text;
        } else {
            if (!out.empty()) out += "; ";
            out += line;
        }
    }
    return out;
}

} // namespace shadowlab::gl
