run --allow-unknown --stub-unmodelled msg-virtual-signal.mod
