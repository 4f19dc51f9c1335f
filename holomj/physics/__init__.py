"""Physics checks of compiled scenes."""
