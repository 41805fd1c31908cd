// textureLook: a Texture statement's appearance and texture frame (see texture_look.hpp).
#include "geometry/texture_look.hpp"

#include <cmath>

#include "grammar/expression.hpp"

namespace shapevo {

glm::vec3 textureTile(const glm::vec3& size, float sx, float sy) {
    const glm::vec3 tile(std::fabs(size.x) / sx, std::fabs(size.y) / sy, std::fabs(size.z) / sx);
    return {tile.x, tile.y, size.z == 0.0f ? tile.x : tile.z};
}

std::uint32_t textureLook(const Grammar& g, const Statement& st, std::vector<Appearance>& looks, const Scope& s,
                          const float* params, const glm::vec3& parentSize, float* evalStack,
                          std::vector<TextureFrame>& frames) {
    const float sx = evaluate(g, st.expr[0], params, &s.size.x, &parentSize.x, evalStack);
    const float sy = evaluate(g, st.expr[1], params, &s.size.x, &parentSize.x, evalStack);
    frames.push_back(TextureFrame{s.origin, s.axes, textureTile(s.size, std::fabs(sx), std::fabs(sy))});
    Appearance look;
    look.color = glm::vec3(1.0f);
    look.material = g.textures[st.slot].material;
    look.texture = std::uint16_t(st.slot + 1);
    look.frame = std::uint32_t(frames.size() - 1);
    looks.push_back(look);
    return std::uint32_t(looks.size() - 1);
}

}  // namespace shapevo
