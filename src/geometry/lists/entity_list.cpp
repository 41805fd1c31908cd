// EntityList's copies (entity_list.hpp): positions in, entities out, bit for bit.
#include "geometry/lists/entity_list.hpp"

namespace shapevo::lists {

void selectEntities(const EntityList& in, std::span<const std::uint32_t> order, EntityList& out) {
    out.clear(in.width);
    for (const std::uint32_t i : order) out.append(in.scopes[i], in.attributes(i));
}

void scopeOrigins(std::span<const Scope> scopes, std::vector<glm::dvec3>& out) {
    out.clear();
    for (const Scope& s : scopes) out.push_back(glm::dvec3(s.origin));
}

}  // namespace shapevo::lists
