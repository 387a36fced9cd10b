#pragma once
// The built-in techniques' catalog rows (techniques/Catalog.h), each
// defined beside its options table: techniques/<Name>Options.cpp, and
// map/options/OptionTable.cpp. None of them needs OpenGL.
#include "techniques/Catalog.h"

namespace shadowlab {

TechniqueKind noneKind();
TechniqueKind mapKind();
TechniqueKind planarKind();
TechniqueKind volumeKind();
TechniqueKind discKind();

} // namespace shadowlab
