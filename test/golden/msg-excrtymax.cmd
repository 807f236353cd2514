run --retry-limit 2 msg-excrtymax.mod
