run --engine machine --retry-limit 2 msg-excrtymax.mod
