signal di_part di
signal do_glue do
at 1 di_part 1
