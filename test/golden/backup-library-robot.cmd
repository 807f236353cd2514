run --robot irb2400-10-1.5 backup-library
