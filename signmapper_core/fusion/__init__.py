"""From detections per pair to one feature per physical sign: fusion, face direction and mounting height."""
