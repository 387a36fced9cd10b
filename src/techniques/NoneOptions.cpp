// Technique "none": its (empty) options table and catalog row (no OpenGL;
// the technique itself is techniques/None.cpp).
#include "techniques/Kinds.h"

namespace shadowlab {

namespace {
/// "none" has no options; its block exists so every technique has one.
struct NoneOptions {
    static constexpr const char* kTechnique = "none";
};
} // namespace

TechniqueKind noneKind() {
    static const OptionTable table = OptionTableFor<NoneOptions>("none").build();
    return {"none", "no shadows: visibility 1 everywhere (the unshadowed baseline)", &table};
}

} // namespace shadowlab
