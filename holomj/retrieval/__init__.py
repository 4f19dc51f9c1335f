"""Asset and material retrieval: text (sentence-transformers), visual (open-clip), size."""
