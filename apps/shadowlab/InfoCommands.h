#pragma once
// `shadowlab techniques` and `shadowlab info`: what the build has
// (InfoCommands.cpp).

namespace shadowlab::tool {

/// The registered techniques and their options tables (the same tables the
/// scene parser, --set, bench --vary and docs/scene-format.md use);
/// `markdown`: as docs/scene-format.md carries them.
int runTechniques(bool markdown);
/// The OpenGL implementation, its limits and the build options.
int runInfo();

} // namespace shadowlab::tool
