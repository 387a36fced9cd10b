"""Outside src/gl, no call of an OpenGL function that OpenGL ES 3.0 (WebGL 2)
lacks or spells differently: code calls src/gl/Calls.h's wrapper instead,
so that a second GL flavour changes src/gl alone. Likewise no shader file
writes a `#version` line or a `binding =` layout: the shader loader
(src/gl/ShaderSource.cpp) writes the version, and SL_BINDING(unit), which
it defines, gives a sampler's or block's unit.

The list below is every such function shadowlab calls or has called
(direct state access, program uniforms by program, texture clears, views
and read-back, timer queries, compute, per-draw-buffer state, clip control,
multi-draw, debug output, glCreate*). A function not on it that ES 3.0
lacks is caught by the ES build, not here. Comments are not looked at.

    python3 gl_calls.py SOURCE_DIR
"""
import os
import re
import sys

ES3_LACKS = [
    "glBindTextureUnit", "glNamedFramebufferTexture", "glNamedFramebufferTextureLayer",
    "glNamedFramebufferDrawBuffer", "glNamedFramebufferDrawBuffers",
    "glNamedFramebufferReadBuffer", "glClearNamedFramebufferfv", "glClearNamedFramebufferfi",
    "glClearNamedFramebufferiv", "glCheckNamedFramebufferStatus", "glBlitNamedFramebuffer",
    "glNamedBufferStorage", "glNamedBufferSubData", "glNamedBufferData",
    "glCopyNamedBufferSubData", "glGetNamedBufferSubData", "glMapNamedBufferRange",
    "glTextureStorage2D", "glTextureStorage3D", "glTextureParameteri", "glTextureParameterfv",
    "glTextureSubImage2D", "glGetTextureSubImage", "glGetTextureImage", "glClearTexSubImage",
    "glClearTexImage", "glGenerateTextureMipmap", "glTextureView", "glVertexArrayAttribFormat",
    "glVertexArrayAttribBinding", "glEnableVertexArrayAttrib", "glVertexArrayVertexBuffer",
    "glVertexArrayElementBuffer", "glProgramUniform1i", "glProgramUniform1f",
    "glProgramUniform1ui", "glProgramUniform1fv", "glProgramUniform2i", "glProgramUniform2f",
    "glProgramUniform2fv", "glProgramUniform3fv", "glProgramUniform4fv", "glProgramUniform4d",
    "glProgramUniformMatrix4fv", "glQueryCounter", "glGetQueryObjectui64v", "glMemoryBarrier",
    "glDispatchCompute", "glEnablei", "glDisablei", "glBlendFunci", "glBlendEquationi",
    "glClipControl", "glMultiDrawElements", "glDebugMessageControl", "glDebugMessageCallback",
    "glCreateBuffers", "glCreateVertexArrays", "glCreateTextures", "glCreateSamplers",
    "glCreateFramebuffers", "glCreateQueries",
]
CALL = re.compile(r"(?<![\w:])(" + "|".join(ES3_LACKS) + r")\s*\(")
DIRS = ["src", "apps", "python"]
ALLOWED = os.path.join("src", "gl")


def code_of(line, in_block):
    """The line without its comments; whether a /* */ comment is still open after it."""
    out, i = "", 0
    while i < len(line):
        if in_block:
            end = line.find("*/", i)
            if end < 0:
                return out, True
            i, in_block = end + 2, False
        elif line.startswith("//", i):
            break
        elif line.startswith("/*", i):
            in_block, i = True, i + 2
        else:
            out += line[i]
            i += 1
    return out, in_block


def main():
    root = os.path.abspath(sys.argv[1])
    problems, files = [], 0
    for top in DIRS:
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            rel_dir = os.path.relpath(dirpath, root)
            if rel_dir == ALLOWED or rel_dir.startswith(ALLOWED + os.sep):
                continue
            for name in sorted(names):
                if not name.endswith((".cpp", ".h")):
                    continue
                files += 1
                rel = os.path.join(rel_dir, name)
                in_block = False
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        code, in_block = code_of(line, in_block)
                        for m in CALL.finditer(code):
                            wrapper = m.group(1)[2].lower() + m.group(1)[3:]
                            problems.append(f"{rel}:{number}: {m.group(1)} (OpenGL ES 3.0 lacks it): call gl::{wrapper} (src/gl/Calls.h)")
    shaders = os.path.join(root, "shaders")
    for name in sorted(os.listdir(shaders)):
        if name == "CMakeLists.txt":
            continue
        with open(os.path.join(shaders, name), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                code, _ = code_of(line, False)
                if re.match(r"\s*#\s*version\b", code):
                    problems.append(f"shaders/{name}:{number}: a #version line (the shader loader writes it)")
                if re.search(r"\bbinding\s*=", code):
                    problems.append(f"shaders/{name}:{number}: a binding = layout (write SL_BINDING(unit))")
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s): calls outside src/gl of the {len(ES3_LACKS)} functions OpenGL ES 3.0 lacks, in {files} files; version and binding lines in shaders/")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
