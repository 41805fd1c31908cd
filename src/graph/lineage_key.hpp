// Lineage keys: 64-bit names of what a derivation's decisions act on, for a genome that answers
// decisions by key (draw_source.hpp, keyed sources). A host element's key names the host graph
// and the element; an element a step creates is named by the step's event and its place in the
// daughter graph; an event (one application of a production) by the production, the keys of the
// elements it matched, how each mother edge lies, and how many times that same match fired
// before. Keys depend on the derivation's structure only, never on a seed or on step numbers,
// so one changed decision leaves the keys of everything outside its descendants as they were.
// mix() is SplitMix64's finalizer over a combination of its two arguments: fixed here, the same
// on every machine.
#pragma once
#include <cstdint>

namespace shapevo::graph {

inline constexpr std::uint64_t mixKey(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a ^ (b + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// Tags that keep the keys of different kinds of decision apart.
namespace key_tag {
inline constexpr std::uint64_t kHost = 0x686f7374;         // host element: mix(mix(kHost, host), 2 id + edge)
inline constexpr std::uint64_t kGlobals = 0x676c6f62;      // global variables' draws
inline constexpr std::uint64_t kRunVariables = 0x72756e76; // options' run variables
inline constexpr std::uint64_t kMatch = 0x6d617463;        // a match: production, images, swaps
inline constexpr std::uint64_t kFire = 0x66697265;         // a match's firing level
inline constexpr std::uint64_t kSalt = 0x73616c74;         // an event's seed
inline constexpr std::uint64_t kFilterOption = 0x666f7074; // the option that filters matches
inline constexpr std::uint64_t kApplyOption = 0x616f7074;  // the option applied
inline constexpr std::uint64_t kOldest = 0x6f6c6473;       // the pick among the oldest matches
inline constexpr std::uint64_t kExpressions = 0x65787072;  // an event's expression draws
inline constexpr std::uint64_t kCondition = 0x636f6e64;    // a match condition's draws
inline constexpr std::uint64_t kDefault = 0x64666c74;      // a decision's value from its seed
}  // namespace key_tag

/// The key of element `id` of host graph `host`.
inline constexpr std::uint64_t hostElementKey(std::uint64_t host, std::uint64_t id, bool edge) {
    return mixKey(mixKey(key_tag::kHost, host), 2 * id + (edge ? 1 : 0));
}
/// The key of daughter element `index` created by the event `eventKey`.
inline constexpr std::uint64_t daughterKey(std::uint64_t eventKey, std::uint64_t index, bool edge) {
    return mixKey(eventKey, 2 * index + (edge ? 1 : 0));
}
/// A decision's default value: 64 bits drawn from its context's seed and its key.
inline constexpr std::uint64_t defaultWord(std::uint64_t seed, std::uint64_t key) {
    return mixKey(mixKey(seed, key_tag::kDefault), key);
}

}  // namespace shapevo::graph
