"""Time per candidate segment of each classifier, as the pipeline calls it (one face box, its candidates).

    python -m bench.bench_classify [--n 300] [--threads 0]

Faces are catalogue templates pasted into a noisy Full-HD frame at 16-160 px;
candidates are the entries of the same colour and shape (the paper's cut).
``--threads`` sets OpenCV's thread count (0 = OpenCV's default: all cores).
"""

from __future__ import annotations

import argparse
import time

import cv2
import numpy as np


def main() -> None:
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.pipeline.classifiers import make_classifier, model_card_path

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    if args.threads:
        cv2.setNumThreads(args.threads)
    catalogue = load_catalogue()
    rng = np.random.default_rng(0)
    frame = rng.integers(60, 200, (1080, 1920, 3)).astype(np.uint8)
    entries = list(catalogue)
    cases = []
    for _ in range(args.n):
        entry = entries[int(rng.integers(len(entries)))]
        size = int(np.exp(rng.uniform(np.log(16), np.log(160))))
        bgr, alpha = catalogue.render(entry.id, size)
        h, w = alpha.shape
        x, y = int(rng.integers(0, 1920 - w)), int(rng.integers(0, 1080 - h))
        a = alpha[..., None].astype(np.float32) / 255
        frame[y:y + h, x:x + w] = (frame[y:y + h, x:x + w] * (1 - a) + bgr * a).astype(np.uint8)
        candidates = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape])]
        cases.append(((x, y, w, h), candidates, entry.id))
    names = ["ncc"] + (["cnn"] if model_card_path(catalogue.folder).is_file() else [])
    print(f"{args.n} face boxes of 16-160 px in a Full-HD frame, candidates = same colour and shape "
          f"(mean {np.mean([len(c[1]) for c in cases]):.1f}); OpenCV threads {cv2.getNumThreads()}")
    for name in names:
        classifier = make_classifier(name, catalogue)
        classifier.classify(frame, cases[0][0], cases[0][1])  # warm-up (model load, caches)
        start = time.perf_counter()
        correct = sum(classifier.classify(frame, bbox, ids).template_id == truth for bbox, ids, truth in cases)
        ms = 1000 * (time.perf_counter() - start) / len(cases)
        print(f"  {name}: {ms:6.2f} ms per candidate segment  (clean templates: {correct}/{len(cases)} right, "
              f"a smoke test, not a recognition figure)")


if __name__ == "__main__":
    main()
