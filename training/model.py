"""The network: four small convolution stages and a linear layer; about 0.4 M weights, 1-2 ms per patch in OpenCV."""

from __future__ import annotations

import torch
from torch import nn


def _conv(cin: int, cout: int) -> list:
    return [nn.Conv2d(cin, cout, 3, padding=1, bias=False), nn.BatchNorm2d(cout), nn.ReLU(inplace=True)]


class SignNet(nn.Module):
    """Plain VGG-like stages: only operators every OpenCV dnn build runs (Conv, BN, ReLU, MaxPool, GAP, Gemm)."""

    def __init__(self, n_classes: int, widths=(24, 48, 96, 160), dropout: float = 0.3):
        super().__init__()
        layers, cin = [], 3
        for w in widths[:-1]:
            layers += _conv(cin, w) + _conv(w, w) + [nn.MaxPool2d(2)]
            cin = w
        layers += _conv(cin, widths[-1])
        self.features = nn.Sequential(*layers)
        self.head = nn.Sequential(nn.AdaptiveAvgPool2d(1), nn.Flatten(), nn.Dropout(dropout),
                                  nn.Linear(widths[-1], n_classes))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.head(self.features(x))
