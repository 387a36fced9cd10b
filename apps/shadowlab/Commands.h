#pragma once
// The tool's subcommands' shared checks and helpers (Commands.cpp); each
// subcommand is a file of its own: RenderCommand, CompareCommand,
// BenchCommand, InfoCommands, ViewCommand; main.cpp parses and dispatches.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Scene.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Text.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::tool {

/// What the techniques noticed about the scene (FrameStats::notes), each once per run.
void printNotes(const std::vector<std::string>& notes);
/// --time: a finite number of seconds (CLI11 reads "nan" and "inf" as numbers); `flag` names it.
void checkTime(double seconds, const std::string& flag);
/// --fps: a finite number of frames per second > 0.
void checkFps(double fps);
/// The scene file at `path` with `overrides` (--set), or the default scene
/// when `path` is empty; `camera` >= 0: a glTF file's camera N (--camera).
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides, int camera = -1);
/// Throws when the context's debug output reported a GL error.
void requireNoGlErrors(const Context& context);
/// Two --set of one path are refused: the later would replace the earlier
/// unchecked, so a bad earlier value would pass without a word (as bench
/// refuses a --vary of a path a --set sets).
void requireDistinctSets(const std::vector<std::string>& overrides);
/// An empty path given on purpose is an error, not "use the default".
void requireNonEmpty(const CLI::App* command, const char* option, const std::string& value, const std::string& what);

} // namespace shadowlab::tool
