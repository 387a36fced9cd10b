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

struct DiscOptions {
    static constexpr const char* kTechnique = "disc";
    /// Comma-separated node names of the disc casters; empty (default):
    /// every casting node whose mesh is a `disc` shape. A named node must
    /// be one. Other casters cast no shadow with this technique.
    std::string casters;
};

/// The options table of "disc".
SHADOWLAB_API const OptionTable& discOptionTable();

} // namespace shadowlab
