"""Review of Sign Mapper layers: the controller between the review dock, the layers and the core."""
