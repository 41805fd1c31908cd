// Helpers shared by the OBJ, PLY and STL parsers: strict number parsing, tokenising,
// and exact-position vertex welding.
#include "mesh/mesh_formats.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

namespace shapevo::meshio {

namespace {
std::string quoted(std::string_view token) {
    constexpr std::size_t kMax = 40;  // keep messages short even for binary garbage
    std::string s(token.substr(0, kMax));
    if (token.size() > kMax) s += "...";
    return "'" + s + "'";
}
}  // namespace

double parseDouble(std::string_view token, const std::string& path, const std::string& where) {
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars refuses a leading '+'
    double value = 0.0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || end != t.data() + t.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
        throw InputError(path, where, "malformed number " + quoted(token));
    if (ec == std::errc::result_out_of_range)
        throw InputError(path, where, "number out of range " + quoted(token));
    return value;
}

long long parseInteger(std::string_view token, const std::string& path, const std::string& where) {
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    long long value = 0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size())
        throw InputError(path, where, "malformed integer " + quoted(token));
    return value;
}

glm::vec3 finitePoint(double x, double y, double z, const std::string& path, const std::string& where) {
    const double c[3] = {x, y, z};
    constexpr double kMax = std::numeric_limits<float>::max();
    for (double v : c)
        if (!std::isfinite(v) || std::fabs(v) > kMax)
            throw InputError(path, where,
                             "non-finite vertex coordinate (" + std::to_string(x) + ", " + std::to_string(y) +
                                 ", " + std::to_string(z) + ")");
    return {float(x), float(y), float(z)};
}

namespace {
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
}  // namespace

std::string_view Tokens::next() {
    std::size_t i = 0;
    while (i < rest_.size() && blank(rest_[i])) ++i;
    std::size_t j = i;
    while (j < rest_.size() && !blank(rest_[j])) ++j;
    std::string_view token = rest_.substr(i, j - i);
    rest_.remove_prefix(j);
    return token;
}

bool Tokens::done() {
    while (!rest_.empty() && blank(rest_.front())) rest_.remove_prefix(1);
    return rest_.empty();
}

std::size_t VertexWelder::KeyHash::operator()(const glm::vec3& p) const {
    std::size_t h = 0;
    for (int a = 0; a < 3; ++a) {
        const float v = p[a] + 0.0f;  // turns -0 into +0 so equal positions hash equally
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = h * 0x9E3779B97F4A7C15ull + bits;
    }
    return h ^ (h >> 29);
}

std::uint32_t VertexWelder::add(const glm::vec3& p) {
    auto [it, inserted] = index_.try_emplace(p, std::uint32_t(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
}

}  // namespace shapevo::meshio
