trace --format jsonl --level statement --to 20 --io controller-cell.io controller-cell.mod
