"""Supplementary plates and printed text: plate templates and SSV ids, OCR, fusion and number checks."""
