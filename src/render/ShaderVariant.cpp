#include "render/ShaderVariant.h"

namespace shadowlab {

namespace {
// The GLSL names of the shared constants (shaders/shadowlab_shared.h).
const char* lightDefine(LightType t) {
    switch (t) {
    case LightType::Directional: return "SL_LIGHT_DIRECTIONAL";
    case LightType::Spot: return "SL_LIGHT_SPOT";
    case LightType::Point: return "SL_LIGHT_POINT";
    }
    return "?";
}
std::string flag(const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); }
} // namespace

std::string ShaderVariant::preamble() const {
    std::string out;
    out += flag("AMBIENT", ambient);
    out += flag("LIGHT", light);
    out += flag("LIGHT_LIST", lightList && !light);
    out += flag("LIGHT_LIST_SHADOWS", lightList && !light && lightListShadows);
    out += std::string("#define LIGHT_TYPE ") + (light ? lightDefine(lightType) : "SL_LIGHT_DIRECTIONAL") + "\n";
    out += flag("HAS_BASE_COLOR_TEXTURE", baseColorTexture);
    out += flag("ALPHA_TEST", alphaTest);
    out += flag("HAS_PROJECTOR", light && projector && lightType == LightType::Spot);
    out += flag("WRITE_SURFACES", writeSurfaces);
    out += flag("SCREEN_VISIBILITY", light && screenVisibility);
    out += flag("OUTPUT_VISIBILITY", light && outputVisibility);
    out += flag("BLENDED", blended);
    if (light && !screenVisibility) out += techniqueDefines;
    return out;
}

gl::ProgramKey ShaderVariant::program() const {
    const bool technique = light && !screenVisibility;
    gl::ProgramKey key{{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}},
                       preamble(),
                       {{"@shadow", technique ? techniqueFile : std::string("shadow_none.glsl")}}};
    key.aliases.emplace_back("@list_shadow", lightList && !light && lightListShadows ? listShadowFile : std::string(kNoListShadow));
    if (technique && !techniqueVertexFile.empty()) key.aliases.emplace_back("@shadow_vertex", techniqueVertexFile);
    if (technique) key.aliases.insert(key.aliases.end(), techniqueIncludes.begin(), techniqueIncludes.end());
    return key;
}

std::vector<ShaderVariant> ShaderVariant::all() {
    std::vector<ShaderVariant> out;
    for (int bits = 0; bits < 256; ++bits)
        for (LightType light : {LightType::Directional, LightType::Spot, LightType::Point}) {
            ShaderVariant v;
            v.ambient = bits & 1;
            v.light = bits & 2;
            v.baseColorTexture = bits & 4;
            v.writeSurfaces = bits & 8;
            v.screenVisibility = bits & 16;
            v.outputVisibility = bits & 32;
            v.blended = bits & 64;
            v.alphaTest = bits & 128;
            if (v.alphaTest && v.blended) continue;  // a blended surface is not alpha-tested
            v.projector = light == LightType::Spot && (bits & 1) && (bits & 2);  // one projector variant per ambient/light pair
            v.lightType = light;
            out.push_back(v);
        }
    return out;
}

} // namespace shadowlab
