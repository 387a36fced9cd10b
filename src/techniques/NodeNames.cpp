#include "techniques/NodeNames.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>

namespace shadowlab {

std::vector<std::size_t> itemsNamed(const FrameInfo& frame, const std::string& list, const std::string& at,
                                    const std::function<bool(std::size_t)>& fits, const std::string& why,
                                    const std::function<bool(std::size_t)>& byDefault) {
    std::vector<std::size_t> chosen;
    const std::vector<std::string> names = text::splitNames(list);
    if (names.empty()) {
        for (std::size_t i = 0; i < frame.items.size(); ++i)
            if (byDefault(i) && fits(i)) chosen.push_back(i);
        return chosen;
    }
    for (const std::string& name : names) {
        bool found = false;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            const int node = frame.items[i].node;
            if (node < 0 || frame.scene.nodes[static_cast<std::size_t>(node)].name != name) continue;
            found = true;
            if (!fits(i)) throw InputError(at + ": node '" + text::escapeControl(name) + "' " + why);
            chosen.push_back(i);
        }
        if (!found) throw InputError(at + ": no node named '" + text::escapeControl(name) + "'");
    }
    return chosen;
}

} // namespace shadowlab
