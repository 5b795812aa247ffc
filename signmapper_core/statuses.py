"""The status words of detections and signs, declared once: what the mapping, the review and the exports write."""

ACCEPTED, REVIEW, REJECTED, MANUAL = "accepted", "review", "rejected", "manual"
STATUSES = (ACCEPTED, REVIEW, REJECTED, MANUAL)
# status -> colour: the review dock's status text and buttons and the detections' layer style
STATUS_COLOURS = {ACCEPTED: "#2e7d32", REVIEW: "#f57c00", REJECTED: "#9e9e9e", MANUAL: "#1565c0"}
