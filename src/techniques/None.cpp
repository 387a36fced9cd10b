#include "techniques/None.h"

#include <shadowlab/Options.h>

namespace shadowlab {

namespace {
/// "none" has no options; its block exists so every technique has one.
struct NoneOptions {
    static constexpr const char* kTechnique = "none";
};

class NoShadow final : public Technique {
public:
    static constexpr const char* summary = "no shadows: visibility 1 everywhere (the unshadowed baseline)";
    bool joinsLightList(const LightView&) const override { return true; }
};
} // namespace

TechniqueEntry noneTechnique() {
    static const OptionTable table = OptionTableFor<NoneOptions>("none").build();
    return entryOf<NoShadow>("none", &table, "shadow_none.glsl");
}

} // namespace shadowlab
