run --allow-unknown unknown-repeated.mod
