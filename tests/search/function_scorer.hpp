// FunctionScorer: a Scorer whose fitness is any function of the chromosome, so the search tests
// can use tiny grammars with a made-up fitness whose exact target distribution is known.
#pragma once
#include <functional>
#include <memory>

#include "score/scorer.hpp"

namespace shapevo::test {

class FunctionScorer final : public Scorer {
public:
    FunctionScorer(const Grammar&, std::function<double(const Chromosome&)> f) : f_(std::move(f)) {}
    std::unique_ptr<ScoreWorkspace> makeWorkspace() const override { return std::make_unique<ScoreWorkspace>(); }
    double fitness(const Chromosome& c, ScoreWorkspace&) const override { return f_(c); }

private:
    std::function<double(const Chromosome&)> f_;
};

}  // namespace shapevo::test
