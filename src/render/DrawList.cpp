#include "render/DrawList.h"

#include "gl/Calls.h"
#include "shadowlab_shared.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cstring>

namespace shadowlab {

void DrawList::upload(const Scene& scene, const std::vector<DrawItem>& items) {
    if (stride_ == 0) {
        GLint alignment = 256;
        glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
        const std::size_t a = static_cast<std::size_t>(std::max(alignment, 1));
        stride_ = (sizeof(shared::DrawUniforms) + a - 1) / a * a;
    }
    gl::reserveBuffer(buffer_, capacity_, std::max<std::size_t>(items.size(), 1) * stride_);
    staging_.assign(items.size() * stride_, 0);
    static const Material fallback;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const DrawItem& item = items[i];
        const Material& m = item.material >= 0 ? scene.materials[static_cast<std::size_t>(item.material)] : fallback;
        shared::DrawUniforms u{};
        u.worldFromObject = item.worldFromObject;
        u.normalFromObject = glm::mat4(glm::inverseTranspose(glm::mat3(item.worldFromObject)));
        u.baseColor = glm::vec4(m.baseColor, item.receivesShadows ? 1.0f : 0.0f);
        u.ambient = glm::vec4(m.ambient, 0.0f);
        u.diffuse = glm::vec4(m.diffuse, 0.0f);
        u.specular = glm::vec4(m.specular, m.shininess);
        u.alpha = glm::vec4(m.alpha, m.alphaCutoff, static_cast<float>(static_cast<int>(m.alphaMode)), m.baseColorTexture >= 0 ? 1.0f : 0.0f);
        std::memcpy(staging_.data() + i * stride_, &u, sizeof u);
    }
    if (!staging_.empty()) gl::namedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(staging_.size()), staging_.data());
}

void DrawList::bind(std::size_t item) const {
    glBindBufferRange(GL_UNIFORM_BUFFER, SL_BINDING_DRAW, buffer_.id(), static_cast<GLintptr>(item * stride_),
                      static_cast<GLsizeiptr>(sizeof(shared::DrawUniforms)));
}

} // namespace shadowlab
