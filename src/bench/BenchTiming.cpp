// bench: a run's timed frames (BenchParts.h): the scene, the same
// unshadowed and at its techniques' baseline, frame by frame through time.
#include "BenchParts.h"

#include <shadowlab/Techniques.h>

#include <algorithm>

namespace shadowlab::bench {

void moveToTime(Scene& scene, const Scene& loaded, double seconds) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) scene.lights[l].position = lightAtTime(loaded.lights[l], seconds).position;
    scene.camera = cameraAtTime(loaded.camera, seconds);
}

namespace {

// The clocked frame's passes and counters into `timed`.
void addClocked(TimedFrames& timed, const FrameStats& frame) {
    double sum = 0.0;
    for (const PassTiming& p : frame.passes) {
        timed.passTimes[p.name].push_back(p.ms);
        if (p.name.find('.') == std::string::npos) sum += p.ms;  // nested scopes are inside their pass
    }
    for (const auto& [name, value] : frame.counters) timed.counters[name].push_back(value);
    timed.passTotal.push_back(sum);
    timed.clock = frame.clock;
    timed.baseLight = frame.baseLight;
}

// Whether the frame's base pass kept a depth pre-pass drawn before it
// (TechniqueHost::beginDepthPrepass; the renderer counts it).
bool drewDepthPrepass(const FrameStats& frame) {
    return std::any_of(frame.counters.begin(), frame.counters.end(), [](const auto& c) { return c.first == "base.depthPrepass"; });
}

// A frame that drew a depth pre-pass, again with its maps kept: no shadow
// pass, so no pre-pass; its base pass's time counted only when it did
// keep them.
void timeUnprepassedBase(Renderer& renderer, const Scene& scene, const RenderOptions& clocked, TimedFrames& timed) {
    RenderOptions kept = clocked;
    kept.cacheShadowMaps = true;
    kept.measureFloors = false;
    const FrameStats again = renderer.render(scene, kept);
    const auto base = std::find_if(again.passes.begin(), again.passes.end(), [](const PassTiming& p) { return p.name == "base"; });
    if (!drewDepthPrepass(again) && base != again.passes.end()) timed.unprepassedBaseTimes.push_back(base->ms);
}

} // namespace

TimedFrames timeFrames(Renderer& renderer, Scene& scene, const Scene& loaded, const BenchOptions& args, const BenchHooks& hooks, Renderer* budgeted) {
    TimedFrames timed;
    // Interleaved: a frame as users get it (no per-pass clock) for
    // the frame time, then a frame with the pass clock for where the
    // time goes. On a software rasteriser the pass clock finishes
    // every pass, which costs the overlap a plain frame has.
    RenderOptions plain;
    plain.width = args.width;
    plain.height = args.height;
    plain.timeSeconds = args.timeSeconds;
    RenderOptions clocked = plain;
    clocked.clock = args.clock;
    clocked.measureFloors = true;
    // The same scene unshadowed: every technique's ratio rests on it.
    Scene unshadowed = scene;
    for (Light& light : unshadowed.lights) light.shadow.technique = "none";
    // And with every light at its technique's baseline (a map at its
    // plainest: one 2D map of the same size, depth, the hardware filter,
    // the lecture's technique), for cascades, PCSS and moment maps' ratio
    // to it; timed only where some light differs from it.
    Scene baseline = scene;
    for (Light& light : baseline.lights) {
        ShadowBaseline b = shadowBaseline(light);
        timed.timedBaseline = timed.timedBaseline || b.differs;
        light.shadow = std::move(b.shadow);
    }
    RenderOptions perLight = plain;
    perLight.groupLights = false;
    timed.timedPerLight = unshadowed.lights.size() >= 3;
    for (int i = 0; i < args.warmup; ++i) {
        renderer.render(scene, plain);
        if (budgeted) {
            RenderOptions cached = plain;
            cached.cacheShadowMaps = true;
            budgeted->render(scene, cached);
        }
        renderer.render(unshadowed, plain);
        if (timed.timedPerLight) renderer.render(unshadowed, perLight);
        if (timed.timedBaseline) renderer.render(baseline, plain);
    }
    // Timed frame i shows the animation at --time + i / --fps: the
    // lights and the camera are moved (outside the timed render())
    // and the three frames of a step see them at the same place.
    for (int i = 0; i < args.frames; ++i) {
        if (hooks.checkpoint) hooks.checkpoint();
        const double t = args.timeSeconds + i / args.fps;
        moveToTime(scene, loaded, t);
        moveToTime(unshadowed, loaded, t);
        plain.timeSeconds = clocked.timeSeconds = t;
        timed.frameTimes.push_back(renderer.render(scene, plain).cpuMs);
        RenderOptions cached = plain;
        cached.cacheShadowMaps = true;
        timed.cachedTimes.push_back(renderer.render(scene, cached).cpuMs);
        if (budgeted) timed.budgetedTimes.push_back(budgeted->render(scene, cached).cpuMs);
        timed.unshadowedTimes.push_back(renderer.render(unshadowed, plain).cpuMs);
        if (timed.timedPerLight) {
            perLight.timeSeconds = t;
            timed.unshadowedPerLightTimes.push_back(renderer.render(unshadowed, perLight).cpuMs);
        }
        if (timed.timedBaseline) {
            moveToTime(baseline, loaded, t);
            timed.baselineTimes.push_back(renderer.render(baseline, plain).cpuMs);
        }
        const FrameStats clockedFrame = renderer.render(scene, clocked);
        addClocked(timed, clockedFrame);
        if (drewDepthPrepass(clockedFrame)) timeUnprepassedBase(renderer, scene, clocked, timed);
        const FrameStats plainClocked = renderer.render(unshadowed, clocked);
        for (const PassTiming& p : plainClocked.passes) timed.unshadowedPassTimes[p.name].push_back(p.ms);
        timed.unshadowedBaseLight = plainClocked.baseLight;
    }
    return timed;
}

} // namespace shadowlab::bench
