#pragma once
// Typed indices: a face number, an edge number and a vertex number are different types, so that
// passing one where another is expected (`across(face, edge)`) does not compile. `IndexMap<Id, T>` is
// per-element data indexed by one of them (a vector that only takes its own index type).
#include <compare>
#include <cstddef>
#include <vector>

namespace foldkit::unfold {

/// An index 0..n-1 into one kind of element; -1 (the default) is "none".
template <class Tag>
class StrongIndex {
 public:
  constexpr StrongIndex() = default;
  constexpr explicit StrongIndex(int index) : index_(index) {}
  /// The plain number, for arrays the typed maps do not cover and for messages.
  constexpr int index() const { return index_; }
  constexpr bool valid() const { return index_ >= 0; }
  friend constexpr auto operator<=>(StrongIndex, StrongIndex) = default;

 private:
  int index_ = -1;
};

using FaceId = StrongIndex<struct FaceTag>;
using EdgeId = StrongIndex<struct EdgeTag>;
using VertexId = StrongIndex<struct VertexTag>;

/// One T per element, indexed by `Id` only.
template <class Id, class T>
class IndexMap {
 public:
  IndexMap() = default;
  explicit IndexMap(int n, const T& value = T{}) : data_(static_cast<std::size_t>(n), value) {}
  T& operator[](Id id) { return data_[static_cast<std::size_t>(id.index())]; }
  const T& operator[](Id id) const { return data_[static_cast<std::size_t>(id.index())]; }
  int size() const { return static_cast<int>(data_.size()); }
  bool empty() const { return data_.empty(); }
  void assign(int n, const T& value) { data_.assign(static_cast<std::size_t>(n), value); }
  void resize(int n, const T& value = T{}) { data_.resize(static_cast<std::size_t>(n), value); }
  auto begin() const { return data_.begin(); }
  auto end() const { return data_.end(); }
  auto begin() { return data_.begin(); }
  auto end() { return data_.end(); }
  friend bool operator==(const IndexMap&, const IndexMap&) = default;

 private:
  std::vector<T> data_;
};

template <class T>
using FaceMap = IndexMap<FaceId, T>;
template <class T>
using EdgeMap = IndexMap<EdgeId, T>;
template <class T>
using VertexMap = IndexMap<VertexId, T>;

/// The ids 0..n-1 in order: `for (EdgeId e : all_ids<EdgeId>(mesh.num_edges()))`.
template <class Id>
class IdRange {
 public:
  class iterator {
   public:
    explicit iterator(int i) : i_(i) {}
    Id operator*() const { return Id(i_); }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator==(const iterator&) const = default;

   private:
    int i_;
  };
  explicit IdRange(int n) : n_(n) {}
  iterator begin() const { return iterator(0); }
  iterator end() const { return iterator(n_); }

 private:
  int n_;
};
template <class Id>
IdRange<Id> all_ids(int n) {
  return IdRange<Id>(n);
}

}  // namespace foldkit::unfold
