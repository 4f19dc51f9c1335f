"""Package data: built-in materials, category tables, the default asset library, examples."""
