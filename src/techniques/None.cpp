#include "techniques/None.h"

#include <shadowlab/Options.h>

namespace shadowlab {

namespace {
/// "none" has no options; its block exists so every technique has one.
struct NoneOptions {
    static constexpr const char* kTechnique = "none";
};

class NoShadow final : public Technique {};
} // namespace

TechniqueEntry noneTechnique() {
    static const OptionTable table = OptionTableFor<NoneOptions>("none").build();
    return {"none", "no shadows: visibility 1 everywhere (the unshadowed baseline)", &table, "shadow_none.glsl",
            [] { return std::make_unique<NoShadow>(); }};
}

} // namespace shadowlab
