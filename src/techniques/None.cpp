#include "techniques/None.h"

namespace shadowlab {

namespace {
class NoShadow final : public Technique {
public:
    bool joinsLightList(const LightView&) const override { return true; }
};
} // namespace

TechniqueEntry noneTechnique() { return entryOf<NoShadow>("none", "shadow_none.glsl"); }

} // namespace shadowlab
