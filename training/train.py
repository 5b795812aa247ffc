"""Train the sign classifier on synthetic faces of a catalogue and write ``<catalogue>/classifier/``.

    python -m training.train --catalogue templates/ch        # what ``make train-classifier`` runs

Reproducible: the same arguments on the same catalogue give the same model
(seeded data, seeded initialisation, fixed thread count). The temperature and
the acceptance threshold are fitted on a separate synthetic validation set with
the candidates cut as the pipeline cuts them (same colour and shape).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import time
from pathlib import Path

import numpy as np
import torch
from torch import nn

from signmapper_core.catalogue import DEFAULT_CATALOGUE_DIR, load_catalogue
from signmapper_core.pipeline.classifiers.calibration import acceptance_threshold
from signmapper_core.pipeline.classifiers.face_patch import standardise
from signmapper_core.pipeline.classifiers.learned import BACKGROUND, CARD_FORMAT, MODEL_DIR

from .dataset import class_shares, generate, labels_for
from .model import SignNet

# the modules of this package that do not make patches: changing them keeps the cached patches valid
NOT_SYNTHESIS = ("train.py", "model.py", "left_out.py")


def catalogue_digest(catalogue) -> str:
    """Hash of catalogue.json and every master image: a model is only valid for the catalogue it was trained on."""
    h = hashlib.sha256((catalogue.folder / "catalogue.json").read_bytes())
    for entry in sorted(catalogue, key=lambda e: e.id):
        h.update((catalogue.folder / entry.png).read_bytes())
    return h.hexdigest()


def candidate_groups(catalogue, class_ids) -> list[list[int]]:
    """Per class, the class indices sharing its colour and shape: what colour and shape leave to the classifier.

    A class is always in its own group: the generic text panels, which the filter leaves out of every other
    group (their layout tells them, not the network), are still trained and validated among their neighbours.
    """
    index = {t: i for i, t in enumerate(class_ids)}
    groups = []
    for tid in class_ids:
        e = catalogue[tid]
        group = [index[o.id] for o in catalogue.filter(colours=[e.colour], shapes=[e.shape])]
        groups.append(group if index[tid] in group else group + [index[tid]])
    return groups


def load_or_make(cache: Path, name: str, make):
    path = cache / f"{name}.npy"
    if path.is_file():
        return np.load(path)
    data = make()
    cache.mkdir(parents=True, exist_ok=True)
    np.save(path, data)
    return data


def shifted(batch: np.ndarray, rng: np.random.Generator, pad: int = 2) -> np.ndarray:
    """Each patch moved by up to ``pad`` pixels: the network must not rely on the exact box."""
    n, s = batch.shape[0], batch.shape[1]
    padded = np.pad(batch, ((0, 0), (pad, pad), (pad, pad), (0, 0)), mode="edge")
    windows = np.lib.stride_tricks.sliding_window_view(padded, (s, s), axis=(1, 2))  # n, dy, dx, 3, s, s
    dy, dx = rng.integers(0, 2 * pad + 1, (2, n))
    return np.ascontiguousarray(windows[np.arange(n), dy, dx].transpose(0, 2, 3, 1))


def to_tensor(batch: np.ndarray) -> torch.Tensor:
    return torch.from_numpy(standardise(batch)).contiguous(memory_format=torch.channels_last)


def predict(model: nn.Module, x: np.ndarray, batch: int = 512) -> np.ndarray:
    model.eval()
    out = []
    with torch.no_grad():
        for i in range(0, len(x), batch):
            out.append(model(to_tensor(x[i : i + batch])).numpy())
    return np.concatenate(out).astype(np.float64)


def restricted_probabilities(logits: np.ndarray, labels: np.ndarray, groups, background: int, temperature: float,
                             rng: np.random.Generator):
    """Softmax over each sample's candidate group plus background, as the pipeline computes it.

    Returns (probability of the best candidate, whether it is the true class). A
    background sample gets the group of a random class: any pick is wrong.
    """
    best_p, correct = [], []
    for z, label in zip(logits, labels):
        group = groups[label] if label != background else groups[int(rng.integers(len(groups)))]
        picked = list(group) + [background]
        zz = z[picked] / temperature
        p = np.exp(zz - zz.max())
        p /= p.sum()
        k = int(np.argmax(p[:-1]))
        best_p.append(p[k])
        correct.append(picked[k] == label)
    return np.array(best_p), np.array(correct)


def fit_temperature(logits, labels, groups, background) -> float:
    """Temperature minimising the negative log-likelihood of the true class over candidates + background."""
    best = (np.inf, 1.0)
    for t in np.exp(np.linspace(np.log(0.3), np.log(5.0), 60)):
        nll = 0.0
        for z, label in zip(logits, labels):
            group = groups[label] if label != background else [label]
            picked = list(dict.fromkeys(list(group) + [background]))
            zz = z[picked] / t
            nll -= zz[picked.index(label)] - (zz.max() + np.log(np.exp(zz - zz.max()).sum()))
        best = min(best, (nll, float(t)))
    return best[1]


def unknown_logit(logits: np.ndarray, labels: np.ndarray, groups, background: int, percentile: float) -> float:
    """The logit that ``percentile`` % of the validation signs read right stay below: a face whose best candidate's
    logit is lower matches no candidate as well as the signs the network reads right (the open set,
    ``pipeline.detect.matches_no_entry``)."""
    fits = []
    for z, label in zip(logits, labels):
        if label == background:
            continue
        group = groups[label]
        if group[int(np.argmax(z[group]))] == label:
            fits.append(z[label])
    return float(np.percentile(fits, percentile))


def export_onnx(model: nn.Module, input_px: int, path: Path) -> None:
    model.eval()
    dummy = torch.zeros(1, 3, input_px, input_px)
    torch.onnx.export(model, dummy, str(path), dynamo=False, opset_version=11, input_names=["patch"],
                      output_names=["logits"], dynamic_axes={"patch": {0: "n"}, "logits": {0: "n"}})


def check_opencv(path: Path, model: nn.Module, sample: np.ndarray) -> float:
    """Largest difference between OpenCV's and PyTorch's logits on a few patches (must be tiny)."""
    import cv2

    net = cv2.dnn.readNetFromONNX(str(path))
    net.setInput(standardise(sample))
    ours = net.forward()
    return float(np.abs(ours - predict(model, sample)).max())


def train(args) -> dict:
    torch.manual_seed(args.seed)
    torch.set_num_threads(args.threads)
    torch.use_deterministic_algorithms(True)
    catalogue = load_catalogue(args.catalogue)
    class_ids = sorted(e.id for e in catalogue) + [BACKGROUND]
    background = len(class_ids) - 1
    digest = catalogue_digest(catalogue)
    synthesis = hashlib.sha256(b"".join(f.read_bytes() for f in sorted(Path(__file__).parent.glob("*.py"))
                                        if f.name not in NOT_SYNTHESIS)).hexdigest()
    tag = f"{digest[:12]}-{synthesis[:8]}-{args.input_px}-{args.margin}-{args.seed}"
    tag += "-dv" if args.design_variants else ""
    cache = Path(args.cache)

    def log(msg):
        print(f"[{time.strftime('%H:%M:%S')}] {msg}", flush=True)

    def gen(labels, seed):
        lab = np.where(labels < 0, -1, labels)
        return generate(args.catalogue, class_ids[:-1], lab, seed, args.input_px, args.margin, args.workers,
                        lambda i, n: log(f"  generated {i}/{n}"), design_variants=args.design_variants)

    train_labels = labels_for(background, args.per_class, args.background, args.seed, class_shares(class_ids[:-1]))
    val_labels = labels_for(background, args.val_per_class, args.val_per_class * 4, args.seed + 1000)
    log(f"{background} classes + background; generating {len(train_labels)} training and {len(val_labels)} "
        f"validation patches")
    x_train = load_or_make(cache, f"train-{tag}-{args.per_class}-{args.background}", lambda: gen(train_labels,
                                                                                                  args.seed))
    x_val = load_or_make(cache, f"val-{tag}-{args.val_per_class}", lambda: gen(val_labels, args.seed + 1000))
    y_train = np.where(train_labels < 0, background, train_labels)
    y_val = np.where(val_labels < 0, background, val_labels)

    model = SignNet(len(class_ids), tuple(args.widths)).to(memory_format=torch.channels_last)
    steps = args.epochs * (len(x_train) // args.batch)
    opt = torch.optim.AdamW(model.parameters(), lr=args.lr, weight_decay=5e-4)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=args.lr, total_steps=steps, pct_start=0.15)
    loss_fn = nn.CrossEntropyLoss(label_smoothing=0.05)
    rng = np.random.default_rng(args.seed)
    groups = candidate_groups(catalogue, class_ids[:-1]) + [[background]]
    start = time.time()
    weights = cache / f"model-{tag}-{args.per_class}-{args.background}-{args.epochs}-{args.batch}-{args.lr}-" \
                      f"{'x'.join(map(str, args.widths))}.pt"
    trained_before = weights.is_file()  # the same patches and settings: only the export is redone
    if trained_before:
        model.load_state_dict(torch.load(weights))
        log(f"loaded the trained weights {weights}")
    for epoch in range(0 if trained_before else args.epochs):
        model.train()
        order = rng.permutation(len(x_train))
        total = 0.0
        for b in range(len(x_train) // args.batch):
            idx = order[b * args.batch : (b + 1) * args.batch]
            x = to_tensor(shifted(x_train[idx], rng))
            y = torch.from_numpy(y_train[idx].astype(np.int64))
            opt.zero_grad()
            loss = loss_fn(model(x), y)
            loss.backward()
            opt.step()
            sched.step()
            total += float(loss.detach())
        logits = predict(model, x_val)
        acc = float((logits.argmax(1) == y_val).mean())
        _, correct = restricted_probabilities(logits, y_val, groups, background, 1.0, np.random.default_rng(0))
        log(f"epoch {epoch + 1}/{args.epochs}: loss {total / max(1, b + 1):.3f}, val accuracy {acc:.4f} "
            f"(among same colour and shape {correct[y_val != background].mean():.4f}), "
            f"{(time.time() - start) / 60:.1f} min")

    if not trained_before:
        torch.save(model.state_dict(), weights)  # a failure in the export below does not cost the training
    logits = predict(model, x_val)
    temperature = fit_temperature(logits, y_val, groups, background)
    best_p, correct = restricted_probabilities(logits, y_val, groups, background, temperature,
                                               np.random.default_rng(0))
    threshold = acceptance_threshold(best_p, correct, args.max_wrong)
    open_set = unknown_logit(logits, y_val, groups, background, args.unknown_percentile)
    out = Path(args.out) if args.out else Path(catalogue.folder) / MODEL_DIR
    out.mkdir(parents=True, exist_ok=True)
    export_onnx(model, args.input_px, out / "model.onnx")
    diff = check_opencv(out / "model.onnx", model, x_val[:32])
    if diff > 1e-3:
        raise RuntimeError(f"OpenCV's result differs from PyTorch's by {diff}")
    signs = y_val != background
    card = {
        "format": CARD_FORMAT,
        "onnx": "model.onnx",
        "classes": class_ids,
        "input_px": args.input_px,
        "margin": args.margin,
        "temperature": round(temperature, 4),
        "accept_threshold": round(threshold, 4),
        "min_score": args.min_score,
        "unknown_logit": round(open_set, 3),
        "training": {
            "command": "python -m training.train " + " ".join(args.argv),
            "catalogue_sha256": digest,
            "samples": int(len(x_train)), "epochs": args.epochs, "seed": args.seed, "widths": list(args.widths),
            "torch": torch.__version__,
            "synthetic_validation": {
                "patches": int(len(x_val)),
                "accuracy_among_same_colour_and_shape": round(float(correct[signs].mean()), 4),
                "accepted_share": round(float((best_p[signs] >= threshold).mean()), 4),
            },
        },
    }
    (out / "model.json").write_text(json.dumps(card, indent=1) + "\n", encoding="utf-8")
    log(f"wrote {out}/model.onnx and model.json: temperature {temperature:.3f}, accept threshold {threshold:.3f}, "
        f"unknown below logit {open_set:.2f}, OpenCV check {diff:.1e}")
    return card


def main(argv=None) -> None:
    import sys

    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--catalogue", default=str(DEFAULT_CATALOGUE_DIR), help="catalogue folder to train for")
    p.add_argument("--out", default=None, help="model folder (default: <catalogue>/classifier)")
    p.add_argument("--per-class", type=int, default=2000, help="training patches per sign class")
    p.add_argument("--background", type=int, default=20000, help="training patches of the background class")
    p.add_argument("--val-per-class", type=int, default=60)
    p.add_argument("--epochs", type=int, default=6)
    p.add_argument("--batch", type=int, default=256)
    p.add_argument("--lr", type=float, default=3e-3)
    p.add_argument("--widths", type=int, nargs=4, default=(24, 48, 96, 160))
    p.add_argument("--input-px", type=int, default=32)
    p.add_argument("--margin", type=float, default=0.12)
    p.add_argument("--max-wrong", type=float, default=0.01, help="wrong share allowed among accepted (validation)")
    p.add_argument("--min-score", type=float, default=0.25, help="probability below which nothing is reported")
    p.add_argument("--unknown-percentile", type=float, default=2.0,
                   help="validation signs read right whose logit is below the open set's limit, in %%")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--design-variants", action="store_true",
                   help="half the faces with their pictogram redrawn (moved, warped, restroked, simplified) and rims "
                        "wider as well as thinner (the shipped model's recipe since 2026-12-02; "
                        "`make train-classifier` passes it); off: the faces of the model shipped before")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--workers", type=int, default=2, help="processes generating patches")
    p.add_argument("--cache", default="/tmp/signmapper-train", help="folder caching generated patches")
    args = p.parse_args(argv)
    args.argv = list(sys.argv[1:] if argv is None else argv)
    train(args)


if __name__ == "__main__":
    main()
