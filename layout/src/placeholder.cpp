namespace foldkit::layout {}
