"""A mapping run compared with an existing sign inventory: the comparison, its layers and its report."""
