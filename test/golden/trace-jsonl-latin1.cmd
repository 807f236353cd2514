trace --format jsonl --rules call-primitive latin1-strings.mod
