namespace foldkit::devices {}
