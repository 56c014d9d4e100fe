// Typed indices: a face, an edge and a vertex number are different types, and per-element data only
// takes its own index type. The compile-time half of this (what does not compile) is checked by concepts.
#include <gtest/gtest.h>

#include <type_traits>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/edge_state.hpp"
#include "foldkit/unfold/ids.hpp"

using namespace foldkit::unfold;

namespace {

template <class E, class F>
concept CanAskAcross = requires(const CutTree& tree, E e, F f) {
  tree.across(e, f);
};
template <class Map, class Id>
concept Indexable = requires(Map& m, Id id) {
  m[id];
};

}  // namespace

static_assert(CanAskAcross<EdgeId, FaceId>);
static_assert(!CanAskAcross<FaceId, EdgeId>, "swapped arguments must not compile");
static_assert(!CanAskAcross<int, int>, "plain numbers must not compile");
static_assert(!std::is_convertible_v<int, EdgeId>, "a number becomes an id only when said so");
static_assert(Indexable<EdgeStates, EdgeId>);
static_assert(!Indexable<EdgeStates, FaceId>);
static_assert(!Indexable<EdgeStates, int>);

TEST(Ids, ADefaultIdIsNoneAndIdsCompareByTheirNumber) {
  EXPECT_FALSE(EdgeId().valid());
  EXPECT_TRUE(EdgeId(0).valid());
  EXPECT_LT(FaceId(2), FaceId(5));
  EXPECT_EQ(VertexId(7).index(), 7);
}

TEST(Ids, AnIndexMapHoldsOneValuePerIdAndAllIdsVisitsEachOnceInOrder) {
  EdgeStates state = all_edges(4, EdgeState::Fold);
  state[EdgeId(2)] = EdgeState::Cut;
  int seen = 0, cuts = 0;
  for (EdgeId e : all_ids<EdgeId>(state.size())) {
    EXPECT_EQ(e.index(), seen++);
    cuts += state[e] == EdgeState::Cut;
  }
  EXPECT_EQ(seen, 4);
  EXPECT_EQ(cuts, 1);
  EXPECT_FALSE(state == all_edges(4, EdgeState::Fold));
}
