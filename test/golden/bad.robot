name "broken"
axis 1 0 -90 290 0 -165 165 250
