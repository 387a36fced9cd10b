#pragma once
/// @file DiscOptions.h
/// Options of technique "disc": shadows of flat discs computed exactly in
/// the light pass, with no shadow pass and no map (Ganovelli et al. exercise
/// 8.6.2-1: UFOs over the ground, and its variation 1, discs in any
/// orientation), under lights[i].shadow.disc in a scene file.
#include <shadowlab/Export.h>
#include <shadowlab/Options.h>

#include <string>

namespace shadowlab {

/// Technique "disc"'s options. What each one does and its default are
/// documented once, in the options table (`shadowlab techniques`,
/// docs/techniques/disc.md); a field's comment here gives its unit and
/// default only.
struct DiscOptions {
    static constexpr const char* kTechnique = "disc";
    std::string casters;  ///< node names, comma-separated; default "" (every disc shape that casts)
};

/// The options table of "disc".
SHADOWLAB_API const OptionTable& discOptionTable();

} // namespace shadowlab
