check --allow-unknown unknown-repeated.mod
