// Technique registry: maps each ShadowTechnique to its module.
#include "techniques/ShadowModule.h"

namespace shadowlab {

namespace {
/// ShadowTechnique::None: the unshadowed baseline, visibility 1 everywhere
/// (lighting.frag's SL_SHADOW_NONE branch). No shadow pass.
class NoShadow final : public ShadowModule {};
} // namespace

std::unique_ptr<ShadowModule> createShadowModule(ShadowTechnique technique) {
    switch (technique) {
    case ShadowTechnique::None: return std::make_unique<NoShadow>();
    }
    return std::make_unique<NoShadow>();
}

} // namespace shadowlab
