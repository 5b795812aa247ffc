"""The drive folder (``shared/drive-format.md``): reading, writing, its images, its clock and its plausibility."""
