# The signals of the spec/motion cases (format: doc/controller.md).
signal do_glue do
signal di_part di
at 2 di_part 1
