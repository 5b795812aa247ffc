"""The classifier strategies a run may choose, by name: declared once for the settings, the CLI and the dialog."""

# name -> what it is, as the dialog offers it
CLASSIFIER_CHOICES = {
    "auto": "Automatic: the learned network where the catalogue has one, else template matching",
    "cnn": "Learned network (CNN trained on the official drawings)",
    "ncc": "Template matching (normalised cross-correlation, Cavegn 2011)",
}
CLASSIFIERS = tuple(CLASSIFIER_CHOICES)
