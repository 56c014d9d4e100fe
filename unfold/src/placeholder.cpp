// Placeholder translation unit so the library target always has a source; remove when real sources land.
namespace foldkit::unfold {}
