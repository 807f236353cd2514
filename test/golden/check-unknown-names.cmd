check unknown-names.mod
