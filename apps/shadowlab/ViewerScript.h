#pragma once
// The viewer's --script files: one action a line, checked when the file is
// read (readScript here), run one a frame by the window loop
// (ViewerSession::runScript in ViewerScript.cpp).
#include <string>
#include <vector>

namespace shadowlab::viewer {

// One action of a --script file, one per line: "set KEY=VALUE", "wait N"
// (frames), "screenshot FILE", "save FILE" (the scene with the settings made,
// as JSON), "show-maps", "show-light", "show-density", "compare [DIR]" (waits
// for the reference; prints the numbers, writes error-<i>.png into DIR),
// "resize W H", "minimize", "restore", "collapse-panel", "expand-panel",
// "layout FILE" (the panel's windows' rectangles and each option shown,
// used or why not, as JSON), "quit"; "#" starts a comment.
struct Action {
    std::string verb, argument;
    int line = 0;
};

/// The actions of the script at `path`. Throws shadowlab::Error naming the
/// file and line for an unknown action or a bad argument.
std::vector<Action> readScript(const std::string& path);

} // namespace shadowlab::viewer
