// Rng lives in base/random.hpp (the 2D graph grammars below genome draw with it too); this header
// keeps the genome layer's include of it where it always was.
#pragma once
#include "base/random.hpp"
