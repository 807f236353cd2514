signal di_part di
