"""Pure geometry: floor plans, doors and windows, furniture under constraints, wall objects."""
