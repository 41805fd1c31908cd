// count / index and the amount filters (amount.hpp).
#include "geometry/lists/amount.hpp"

namespace shapevo::lists {

void writeIndices(std::span<double> index) {
    for (std::size_t i = 0; i < index.size(); ++i) index[i] = double(i);
}

std::uint32_t countInto(EntityList& list, std::uint32_t slot) {
    for (std::uint32_t i = 0; i < list.size(); ++i) list.attributes(i)[slot] = double(i);
    return list.size();
}

namespace {
bool insideWindow(std::uint64_t index, std::uint64_t from, std::uint64_t amount) {
    return index >= from && index - from < amount;  // no overflow for from + amount beyond 2^64
}
}  // namespace

void amountFilter(std::uint32_t n, std::uint64_t from, std::uint64_t amount, std::vector<std::uint32_t>& kept,
                  std::vector<std::uint32_t>& rest) {
    kept.clear();
    rest.clear();
    for (std::uint32_t i = 0; i < n; ++i) (insideWindow(i, from, amount) ? kept : rest).push_back(i);
}

void amountFilterByGroup(const Grouping& groups, std::uint64_t from, std::uint64_t amount, std::vector<std::uint32_t>& kept,
                         std::vector<std::uint32_t>& rest) {
    kept.clear();
    rest.clear();
    // A member's index within its group = how many of its group came before it in list order.
    const std::uint32_t n = std::uint32_t(groups.groupOf.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t g = groups.groupOf[i];
        const std::span<const std::uint32_t> members = groups.group(g);
        // Members are in list order: binary search for i's index in its group.
        std::uint32_t lo = 0, hi = std::uint32_t(members.size());
        while (lo < hi) {
            const std::uint32_t mid = (lo + hi) / 2;
            if (members[mid] < i) lo = mid + 1; else hi = mid;
        }
        (insideWindow(lo, from, amount) ? kept : rest).push_back(i);
    }
}

}  // namespace shapevo::lists
