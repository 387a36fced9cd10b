// Technique "map": the shadow atlas (atlas/Atlas.h).
#include "techniques/map/atlas/Atlas.h"

#include "core/AtlasLayout.h"
#include "geometry/LightTiles.h"
#include "gl/Calls.h"
#include "techniques/map/Cache.h"
#include "techniques/map/Variants.h"
#include "techniques/map/atlas/Tiles.h"
#include "techniques/map/fit/Cameras.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace shadowlab::map {


void MapAtlas::layout(TechniqueHost& host, const FrameInfo& frame, std::map<int, MapLight*>& lights) {
    const ShadowAtlasSettings& settings = frame.scene.shadowAtlas;
    makeTexture(settings, host.glInfo().maxTextureSize);
    const Requests requests = gatherRequests(frame, lights);
    const double texelBudget = settings.budgetPerPixel > 0.0f ? static_cast<double>(settings.budgetPerPixel) * frame.viewport.x * frame.viewport.y : 0.0;
    const AtlasLayout layout = place(requests, settings, texelBudget);
    tiles_.clear();
    pending_.clear();
    Assigned assigned;
    assigned.casters = casterInputs(frame);
    for (std::size_t k = 0; k < requests.order.size(); ++k) assignTiles(frame, requests, k, *lights.at(requests.order[k]), layout, assigned);
    applyBudget(host, frame, assigned);
    // Where this frame's drawn tiles are cleared (draw, with the first light):
    // only the texels their casters may cover; the lookup finds the rest lit.
    clears_.clear();
    for (const auto& [index, p] : lights)
        for (int t = 0; t < p->atlas->count; ++t) {
            const auto f = static_cast<std::size_t>(t);
            const TexelRect& c = p->atlas->covered[f];
            if (!p->atlas->draw[f] || c.empty()) continue;
            const glm::ivec2 o = p->atlas->origins[f];
            clears_.emplace_back(o.x + c.x0, o.y + c.y0, c.x1 - c.x0, c.y1 - c.y0);
        }
    noteFit(host, frame, assigned, layout, texelBudget);
    gl::reserveBuffer(tileBuffer_, tileBytes_, std::max<std::size_t>(tiles_.size(), 1) * sizeof(shared::AtlasTile));
    if (!tiles_.empty())
        gl::namedBufferSubData(tileBuffer_.id(), 0, static_cast<GLsizeiptr>(tiles_.size() * sizeof(shared::AtlasTile)), tiles_.data());
    texelsUsed_ = layout.texelsUsed;
}

void MapAtlas::makeTexture(const ShadowAtlasSettings& settings, int limit) {
    if (settings.size > limit)
        throw InputError("shadowAtlas.size: " + std::to_string(settings.size) + " texels is past this GPU's limit of " + std::to_string(limit));
    if (size_ != settings.size) {
        depth_ = gl::Texture(GL_TEXTURE_2D);
        gl::textureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, settings.size, settings.size);
        fbo_ = gl::Framebuffer();
        gl::namedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        gl::namedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        gl::namedFramebufferReadBuffer(fbo_.id(), GL_NONE);
        gl::checkFramebuffer(fbo_, "shadow atlas");
        size_ = settings.size;
        drawn_.clear();  // a new texture holds no maps
        last_.requests.clear();
    }
    if (!nearest_) {
        nearest_ = atlasSampler(false);
        compare_ = atlasSampler(true);
    }
}

MapAtlas::Requests MapAtlas::gatherRequests(const FrameInfo& frame, const std::map<int, MapLight*>& lights) {
    // Each light's requests: a spot's tile at the side its reach on screen
    // asks for; each face of a point light's cube at the side of what that
    // face sees of its reach (the receivers within it) on screen, at most
    // the whole reach's. A light out of view asks for none.
    const ShadowAtlasSettings& settings = frame.scene.shadowAtlas;
    Bounds receivers;
    for (std::size_t i = 0; i < frame.items.size(); ++i)
        if (frame.items[i].receivesShadows) receivers.add(frame.itemBounds[i]);
    // The sides asked for last frame hold while the atlas's sizing settings do.
    const glm::vec3 sizing(settings.texelsPerPixel, static_cast<float>(settings.minTile), static_cast<float>(settings.maxTile));
    if (sizing != last_.sizing) last_.sides.clear();
    last_.sizing = sizing;
    Requests out;
    for (const auto& [index, p] : lights) {
        const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
        const float extent = screenExtent(light, frame);
        // Tiles are powers of two (core/AtlasLayout): map.size caps them at
        // the power of two within it (a 768 map's tiles are at most 512).
        const int maxSide = static_cast<int>(std::bit_floor(static_cast<unsigned>(std::min(settings.maxTile, p->options.size))));
        const int minSide = std::min(settings.minTile, maxSide);
        out.order.push_back(index);
        out.first.push_back(out.requests.size());
        std::array<int, 6>& last = last_.sides[index];  // the sides it asked for last frame (0: none)
        const auto ask = [&out, owner = index](AtlasRequest r) {  // (clang cannot capture the binding itself)
            out.requests.push_back(r);
            out.asked.emplace_back(owner, r);
        };
        if (!(extent > 0.0f)) {
            ask({0, minSide});
            last.fill(0);
            continue;
        }
        if (!p->cube()) {
            last[0] = tileSideKeeping(extent, settings.texelsPerPixel, minSide, maxSide, last[0]);
            ask({1, last[0]});
            continue;
        }
        const float range = light.range > 0.0f ? light.range : std::numeric_limits<float>::infinity();
        for (std::size_t f = 0; f < 6; ++f) {
            const std::optional<float> seen =
                screenExtentOf(cubeFaceReach(light.position, range, static_cast<int>(f), receivers), frame.clipFromWorld, frame.viewport);
            last[f] = tileSideKeeping(seen ? std::min(*seen, extent) : extent, settings.texelsPerPixel, minSide, maxSide, last[f]);
            ask({1, last[f]});
        }
    }
    for (auto it = last_.sides.begin(); it != last_.sides.end();)  // lights gone from the atlas
        it = lights.count(it->first) ? std::next(it) : last_.sides.erase(it);
    return out;
}

AtlasLayout MapAtlas::place(const Requests& r, const ShadowAtlasSettings& settings, double texelBudget) {
    // The same lights asking for the same tiles: the same places, so that
    // kept maps stay where their records say.
    const bool samePlaces = texelBudget == last_.budget && r.asked.size() == last_.requests.size() &&
                            std::equal(r.asked.begin(), r.asked.end(), last_.requests.begin(), [](const auto& a, const auto& b) {
                                return a.first == b.first && a.second.tiles == b.second.tiles && a.second.side == b.second.side;
                            });
    const AtlasLayout layout = samePlaces ? last_.layout : packAtlas(r.requests, settings.size, settings.minTile, texelBudget);
    if (!samePlaces) drawn_.clear();  // the tiles moved: nothing is where it was
    last_.requests = r.asked;
    last_.layout = layout;
    last_.budget = texelBudget;
    if (!layout.fits) {
        std::size_t tiles = 0;
        for (const AtlasRequest& request : r.requests) tiles += static_cast<std::size_t>(request.tiles);
        throw InputError("shadowAtlas.size: " + std::to_string(tiles) + " tiles of at least " + std::to_string(settings.minTile) + "^2 texels (shadowAtlas.minTile) do not fit in " +
                    std::to_string(settings.size) + "^2; raise shadowAtlas.size or lower shadowAtlas.minTile");
    }
    return layout;
}

void MapAtlas::assignTiles(const FrameInfo& frame, const Requests& requests, std::size_t k, MapLight& p, const AtlasLayout& layout, Assigned& out) {
    const int index = requests.order[k];
    const std::size_t first = requests.first[k];
    p.atlas->first = static_cast<int>(tiles_.size());
    p.atlas->count = requests.requests[first].tiles == 0 ? 0 : (p.cube() ? 6 : 1);
    p.atlas->sides.fill(0);
    int largestAsked = 0, given = 0;  // its largest tile's side, asked for and placed
    for (int t = 0; t < p.atlas->count; ++t) {
        const auto f = static_cast<std::size_t>(t);
        const AtlasPlacement& place = layout.placed[first + f];  // one request a tile
        largestAsked = std::max(largestAsked, place.shrunkFrom);
        given = std::max(given, place.side);
        p.atlas->sides[f] = place.side;
        p.atlas->origins[f] = place.origins[0];
        // The texels its casters may cover: only those are cleared and drawn.
        const glm::mat4 clip = p.cube() ? p.cubeCamera().faceClipFromWorld[f] : p.camera.clipFromWorld();
        TexelRect covered{};
        Hash key;
        key.value(clip).value(out.casters).value(p.options.slopeBias).value(p.options.offsetUnits).value(p.options.cullFront).value(place.side).value(place.origins[0]);
        std::vector<std::size_t>& seen = p.atlas->casters[f];
        seen.clear();
        for (std::size_t i = 0; i < frame.items.size(); ++i)
            if (castsIntoTile(frame, p, t, i)) {
                covered = covered.united(projectedRect(clip, frame.itemBounds[i], place.side));
                key.value(i);
                seen.push_back(i);
            }
        p.atlas->covered[f] = covered;
        p.atlas->key[f] = key.h;
        const shared::AtlasTile record = tileOf(clip, p.cube() ? 1.0f : p.camera.clipFromView[1][1], place.origins[0], place.side, size_, covered);
        pending_.push_back(record);
        tiles_.push_back(record);
        // Kept, drawn again, or drawn again if the budget allows.
        const Drawn& before = drawn_[index][f];
        p.atlas->draw[f] = true;
        if (!frame.cacheShadowMaps || !before.valid) {
            ++out.mustDraw;
        } else if (before.key == key.h) {
            p.atlas->draw[f] = false;
        } else {
            out.changed.push_back({&p, index, t, before.frame});
        }
    }
    if (given < largestAsked && ++out.shrunkCount <= 8)
        out.shrunk += (out.shrunk.empty() ? "" : ", ") + std::string("lights[") + std::to_string(index) + "] " + std::to_string(largestAsked) + " -> " + std::to_string(given);
}

void MapAtlas::applyBudget(TechniqueHost& host, const FrameInfo& frame, Assigned& assigned) {
    // The budget: the changed tiles undrawn longest first, the rest keep
    // their map and the record it was drawn with.
    const int budget = frame.scene.shadowAtlas.updateBudget;
    behind_ = false;
    if (budget <= 0 || !frame.cacheShadowMaps) return;
    std::vector<Changed>& changed = assigned.changed;
    std::stable_sort(changed.begin(), changed.end(), [](const Changed& a, const Changed& b) { return a.since < b.since; });
    int room = std::max(budget - assigned.mustDraw, 0);
    for (const Changed& c : changed) {
        if (room > 0) {
            --room;
            continue;
        }
        const auto f = static_cast<std::size_t>(c.tile);
        const Drawn& before = drawn_[c.index][f];
        c.p->atlas->draw[f] = false;
        behind_ = true;
        c.p->atlas->covered[f] = before.covered;
        tiles_[static_cast<std::size_t>(c.p->atlas->first + c.tile)] = before.record;
    }
    if (assigned.mustDraw > budget)
        host.note("shadowAtlas.updateBudget: " + std::to_string(assigned.mustDraw) + " tiles were new to their place in the atlas and drawn, more than the budget of " +
                  std::to_string(budget) + " a frame (a tile's place changes when a light's size on screen does)");
}

void MapAtlas::noteFit(TechniqueHost& host, const FrameInfo& frame, const Assigned& assigned, const AtlasLayout& layout, double texelBudget) const {
    const ShadowAtlasSettings& settings = frame.scene.shadowAtlas;
    const bool byBudget = texelBudget > 0.0 && texelBudget < static_cast<double>(size_) * size_;
    const std::string fitTo = byBudget ? "the budget of " + std::to_string(static_cast<long long>(texelBudget)) + " texels (shadowAtlas.budgetPerPixel " +
                                             text::numberText(settings.budgetPerPixel) + " x " + std::to_string(frame.viewport.x) + "x" +
                                             std::to_string(frame.viewport.y) + " pixels)"
                                       : std::to_string(size_) + "^2 texels";
    if (assigned.shrunkCount > 0)
        host.note("shadowAtlas: " + std::to_string(assigned.shrunkCount) + " light(s) got smaller tiles than their size on screen asks for, to fit " + fitTo + " (" +
                  assigned.shrunk + (assigned.shrunkCount > 8 ? ", and " + std::to_string(assigned.shrunkCount - 8) + " more" : "") + "); raise " +
                  (byBudget ? "shadowAtlas.budgetPerPixel" : "shadowAtlas.size") + " or lower shadowAtlas.texelsPerPixel");
    if (layout.overBudget)
        host.note("shadowAtlas: the tiles at shadowAtlas.minTile (" + std::to_string(settings.minTile) + ") alone take " +
                  std::to_string(static_cast<long long>(layout.texelsUsed)) + " texels, more than " + fitTo + "; lower shadowAtlas.minTile");
}

void MapAtlas::draw(TechniqueHost& host, const FrameInfo& frame, const MapLight& p, int index) {
    batch_.update(frame);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    // The clears of every light's tiles, with the first light drawn this
    // frame: glClearTexSubImage before any caster is queued (llvmpipe fills
    // the texels on the CPU; after a draw into the atlas it would first
    // wait for the rasteriser, once per call). Then this light's share of
    // them, kept or drawn.
    for (const glm::ivec4& r : clears_) gl::clearTexSubImage(depth_.id(), 0, r.x, r.y, 0, r.z, r.w, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &kAtlasFar);
    clears_.clear();
    double cleared = 0.0;
    int kept = 0, redrawn = 0;
    for (int t = 0; t < p.atlas->count; ++t) {
        const auto f = static_cast<std::size_t>(t);
        if (!p.atlas->draw[f]) {
            ++kept;  // its map from an earlier frame (cacheShadowMaps)
            continue;
        }
        drawn_[index][f] = {true, p.atlas->key[f], frame.frameIndex, pending_[static_cast<std::size_t>(p.atlas->first + t)], p.atlas->covered[f]};
        ++redrawn;
        const TexelRect& c = p.atlas->covered[f];
        if (!c.empty()) cleared += static_cast<double>(c.x1 - c.x0) * static_cast<double>(c.y1 - c.y0);
    }
    const std::size_t drawn = drawTiles(host, frame, p);
    host.count("triangles", static_cast<double>(drawn));
    host.count("atlasTiles", static_cast<double>(p.atlas->count));
    double texels = 0.0;
    for (int t = 0; t < p.atlas->count; ++t) texels += static_cast<double>(p.atlas->sides[static_cast<std::size_t>(t)]) * p.atlas->sides[static_cast<std::size_t>(t)];
    host.count("tileSide", static_cast<double>(*std::max_element(p.atlas->sides.begin(), p.atlas->sides.end())));  // its largest
    host.count("tileTexels", texels);
    host.count("clearedTexels", cleared);
    host.count("tilesDrawn", redrawn);
    host.count("tilesKept", kept);
    if (p.atlas->first == 0) host.count("atlasTexels", texelsUsed_);  // the whole atlas's, once a frame: with its first tile
}

std::size_t MapAtlas::drawTiles(TechniqueHost& host, const FrameInfo& frame, const MapLight& p) {
    // The opaque casters in one batch, one call per tile; those with holes one by one.
    const gl::Program& batched = host.program({{{GL_VERTEX_SHADER, "shadow_atlas_batch.vert"}, {GL_FRAGMENT_SHADER, "shadow_atlas_batch.frag"}}, ""});
    const gl::Program& single = host.program(
        {{{GL_VERTEX_SHADER, "shadow_atlas_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}}, DepthPassVariant{MapFormat::Depth32F, true}.defines()});  // casters with holes
    gl::RenderState state;
    state.noColor();
    state.polygonOffset = !p.options.cullFront && (p.options.slopeBias != 0.0f || p.options.offsetUnits != 0.0f);
    state.offsetFactor = p.options.slopeBias;
    state.offsetUnits = p.options.offsetUnits;
    state.cull = p.options.cullFront ? gl::Cull::Front : gl::Cull::None;
    state.clipDistances = 4;  // each tile's sides (shadow_atlas_depth.vert)
    // cullFront: closed casters by their far sides (mirrored ones with back
    // faces culled), open ones whole with the offset (passes/CasterDraw.h).
    gl::RenderState mirrored = state;
    mirrored.cull = gl::Cull::Back;
    gl::RenderState open = state;
    open.cull = gl::Cull::None;
    open.polygonOffset = p.options.slopeBias != 0.0f || p.options.offsetUnits != 0.0f;
    const auto winding = [&](std::size_t i) { return i < frame.itemWinding.size() ? frame.itemWinding[i] : 0; };
    std::size_t drawn = 0;
    // The casters `wanted` (in order): the opaque in one batch, those with holes one by one.
    const auto drawCasters = [&](const std::vector<std::size_t>& wanted) {
        drawn += batch_.draw(batched, wanted);
        if (std::all_of(wanted.begin(), wanted.end(), [&](std::size_t i) { return batch_.holds(i); })) return;
        host.drawItems(ItemFilter::Casters, single, [&](std::size_t i) {
            const bool draw = !batch_.holds(i) && std::binary_search(wanted.begin(), wanted.end(), i);
            if (draw) drawn += frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount();
            return draw;
        });
    };
    host.apply(state);
    for (int t = 0; t < p.atlas->count; ++t) {
        const auto f = static_cast<std::size_t>(t);
        if (!p.atlas->draw[f] || p.atlas->covered[f].empty()) continue;
        const glm::ivec2 o = p.atlas->origins[f];
        glViewport(o.x, o.y, p.atlas->sides[f], p.atlas->sides[f]);
        const glm::mat4 clip = p.cube() ? p.cubeCamera().faceClipFromWorld[f] : p.camera.clipFromWorld();
        gl::programUniformMatrix4fv(batched.id(), 0, 1, GL_FALSE, &clip[0][0]);
        gl::programUniformMatrix4fv(single.id(), 0, 1, GL_FALSE, &clip[0][0]);
        // The casters this tile's camera can see (layout found them).
        if (!p.options.cullFront) {
            drawCasters(p.atlas->casters[f]);
            continue;
        }
        for (const int sides : {1, -1, 0}) {
            std::vector<std::size_t> group;
            for (std::size_t i : p.atlas->casters[f])
                if (winding(i) == sides) group.push_back(i);
            if (group.empty()) continue;
            host.apply(sides > 0 ? state : sides < 0 ? mirrored : open);
            drawCasters(group);
        }
        host.apply(state);
    }
    return drawn;
}

void MapAtlas::bind() const {
    gl::bindTextureUnit(SL_UNIT_ATLAS, depth_.id());
    glBindSampler(SL_UNIT_ATLAS, nearest_.id());
    gl::bindTextureUnit(SL_UNIT_ATLAS_COMPARE, depth_.id());
    glBindSampler(SL_UNIT_ATLAS_COMPARE, compare_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_ATLAS_TILES, tileBuffer_.id());
}

glm::vec4 MapAtlas::shadowOf(const MapLight& p) {
    return {static_cast<float>(p.atlas->first), static_cast<float>(p.atlas->count), p.options.normalBias, p.options.filter == MapFilter::Hardware ? 1.0f : 0.0f};
}

} // namespace shadowlab::map
