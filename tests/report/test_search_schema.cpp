// The weight search's file schema: the weights a reader takes from search_best.csv's header are
// the ones its writer put there, and every file starts with the search's id.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "report/search_schema.hpp"

namespace fsweep {
namespace {

TEST(SearchSchema, SearchBestsWeightsAreReadBackFromItsHeader) {
  const std::vector<std::string> weights{"w1", "w2", "w3", "w4"};
  EXPECT_EQ(search_best_weights(search_best_columns(weights)), weights);
  EXPECT_TRUE(search_best_weights(search_best_columns({})).empty());
  EXPECT_TRUE(search_best_weights({"search_id", "rank"}).empty());  // no objective column
}

TEST(SearchSchema, EveryFileStartsWithTheSearchIdAndNamesItsBehaviour) {
  const std::vector<std::string> weights{"w1", "w2"};
  for (const auto& h : {behaviours_columns(weights), search_summary_columns(), search_best_columns(weights),
                        search_ranks_columns(weights), search_heatmaps_columns(), vectors_columns(weights)}) {
    ASSERT_FALSE(h.empty());
    EXPECT_EQ(h.front(), kSearchIdColumn);
  }
  for (const auto& h : {behaviours_columns(weights), search_best_columns(weights),
                        search_ranks_columns(weights), search_heatmaps_columns(), vectors_columns(weights)}) {
    EXPECT_NE(std::find(h.begin(), h.end(), kBehaviourIdColumn), h.end());
  }
  const auto b = behaviours_columns(weights);
  EXPECT_NE(std::find(b.begin(), b.end(), "w2.max"), b.end());
  EXPECT_NE(std::find(b.begin(), b.end(), kInstanceColumn), b.end());
}

}  // namespace
}  // namespace fsweep
