#pragma once
// What techniques whose options name nodes share (planar's receivers,
// disc's casters): the items an option's list of node names picks.
#include "techniques/Technique.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

/// The items picked by `list`, comma-separated node names (text::splitNames).
/// Each named node must exist and `fits` each of its items, else an error
/// "<at>: ..." naming the node and `why` it does not fit. With no names,
/// every item that `byDefault` accepts and `fits`.
std::vector<std::size_t> itemsNamed(const FrameInfo& frame, const std::string& list, const std::string& at,
                                    const std::function<bool(std::size_t)>& fits, const std::string& why,
                                    const std::function<bool(std::size_t)>& byDefault);

} // namespace shadowlab
