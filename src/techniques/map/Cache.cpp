// Technique "map": the maps' inputs as one hash (Cache.h).
#include "techniques/map/Cache.h"


#include <shadowlab/MapOptions.h>
#include <shadowlab/Options.h>

#include <any>
#include <string>

namespace shadowlab::map {

namespace {

void addLight(Hash& h, const Light& light, const MapOptions& o) {
    h.value(static_cast<int>(light.type));
    h.value(light.position);
    h.value(light.direction);
    h.value(light.range);
    h.value(light.innerConeDeg);
    h.value(light.outerConeDeg);
    h.text(light.shadow.technique);
    // The frame's options field by field, as JSON writes them (no padding bytes).
    const OptionTable& table = mapOptionTable();
    const std::any options = o;
    for (const OptionField& field : table.fields) h.text(table.valueText(field, options));
}

} // namespace

std::uint64_t mapInputs(const FrameInfo& frame, const std::map<int, MapOptions>& options) {
    Hash h;
    h.value(frame.sceneUpload);
    h.value(frame.clipFromWorld);
    h.value(frame.viewport);
    for (const auto& [index, o] : options) {
        h.value(index);
        addLight(h, frame.scene.lights[static_cast<std::size_t>(index)], o);
    }
    h.value(frame.items.size());
    for (const DrawItem& item : frame.items) {
        h.value(item.mesh);
        h.value(item.worldFromObject);
        h.value(item.castsShadows);
        h.value(item.receivesShadows);
        h.value(item.material);
        if (item.material >= 0) {
            const Material& m = frame.scene.materials[static_cast<std::size_t>(item.material)];
            h.value(static_cast<int>(m.alphaMode));
            h.value(m.alphaCutoff);
            h.value(m.alpha);
            h.value(m.baseColor);
            h.value(m.baseColorTexture);
        }
    }
    return h.h;
}

} // namespace shadowlab::map
