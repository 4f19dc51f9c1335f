"""Text to scene: plan -> retrieve -> layout -> compile -> spawn-and-drop -> validate -> export."""
