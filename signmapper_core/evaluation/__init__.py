"""How well a run mapped a drive with ground truth: accuracy, families, panels, plates and evidence of misreadings."""
