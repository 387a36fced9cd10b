// The scene file's `shadowAtlas`: the size of the depth texture that the
// lights with `shadow.map.atlas` share, and how their tiles are sized
// (docs/scene-format.md; Scene.h: ShadowAtlasSettings).
#include "scene/SceneParts.h"

namespace shadowlab::scenefile {

namespace {

bool powerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }

int powerOfTwoAt(const Reader& r, const char* key, int def, int minimum, int maximum) {
    const int v = r.integer(key, def, minimum, maximum);
    if (!powerOfTwo(v)) r.child(key).fail("expected a power of two, got " + std::to_string(v));
    return v;
}

} // namespace

ShadowAtlasSettings readShadowAtlas(const Reader& r) {
    r.requireObject();
    r.checkKeys({"size", "texelsPerPixel", "minTile", "maxTile", "budgetPerPixel", "updateBudget"});
    ShadowAtlasSettings s;
    s.size = powerOfTwoAt(r, "size", s.size, 256, 16384);
    s.texelsPerPixel = r.number("texelsPerPixel", s.texelsPerPixel);
    if (!(s.texelsPerPixel >= 0.0625f && s.texelsPerPixel <= 16.0f))
        r.child("texelsPerPixel").fail("expected 0.0625..16, got " + Reader::fmt(s.texelsPerPixel));
    s.maxTile = powerOfTwoAt(r, "maxTile", std::min(s.maxTile, s.size), 8, s.size);
    s.minTile = powerOfTwoAt(r, "minTile", std::min(s.minTile, s.maxTile), 8, s.maxTile);
    s.budgetPerPixel = r.number("budgetPerPixel", s.budgetPerPixel);
    if (!(s.budgetPerPixel >= 0.0f && s.budgetPerPixel <= 4096.0f))
        r.child("budgetPerPixel").fail("expected 0..4096 texels a pixel of the frame, got " + Reader::fmt(s.budgetPerPixel));
    s.updateBudget = r.integer("updateBudget", s.updateBudget, 0, 65536);
    return s;
}

} // namespace shadowlab::scenefile
