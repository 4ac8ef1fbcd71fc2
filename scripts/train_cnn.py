#!/usr/bin/python3
"""Train the thesis's 1D CNN (seed 000 §5.2, digest §8) on windows exported by Athlos and write ONNX.

    athlos train p.athlos --model m --input imu --window 4 --step 2 --export-windows win/
    /usr/bin/python3 scripts/train_cnn.py win/ --out m.onnx        # also writes m.json
    athlos train p.athlos --model m --input imu --classifier cnn --onnx m.onnx

Network (DCNN): conv 8×32 + ReLU → max-pool 4/2 → conv 16×16 + ReLU → max-pool 6/4 → FC 64 → FC 64 →
softmax; Adam 1e-3, batch 200, Gaussian input noise, dropout on the FC layers, early stopping on a
held-out subject split. The 1D layers are written as 2D ones with 1×k kernels (input N×C×1×L), which
OpenCV's ONNX importer reads in every 4.x version. Needs Debian's python3-torch (and numpy); it is a
tool for users, not a build or CI dependency. Inputs are normalised per channel (mean, SD over the
training windows); the JSON description carries that, the classes and the columns, and --cv K
adds a leave-subjects-out cross-validation (K folds of whole subjects) to it.
"""
import argparse
import json
import os
import sys

import numpy as np
import torch
import torch.nn as nn


class Dcnn(nn.Module):
    def __init__(self, channels, length, classes, conv1=8, kernel1=32, conv2=16, kernel2=16, hidden=64, dropout=0.7):
        super().__init__()
        kernel1 = min(kernel1, max(2, length // 4))
        kernel2 = min(kernel2, max(2, length // 8))
        self.features = nn.Sequential(
            nn.Conv2d(channels, conv1, (1, kernel1)), nn.ReLU(), nn.MaxPool2d((1, 4), (1, 2)),
            nn.Conv2d(conv1, conv2, (1, kernel2)), nn.ReLU(), nn.MaxPool2d((1, 6), (1, 4)), nn.Flatten())
        n = self.features(torch.zeros(1, channels, 1, length)).shape[1]
        self.head = nn.Sequential(
            nn.Linear(n, hidden), nn.ReLU(), nn.Dropout(dropout),
            nn.Linear(hidden, hidden), nn.ReLU(), nn.Dropout(dropout),
            nn.Linear(hidden, classes))

    def forward(self, x):
        return self.head(self.features(x))


class WithSoftmax(nn.Module):
    def __init__(self, net):
        super().__init__()
        self.net = net

    def forward(self, x):
        return torch.softmax(self.net(x), dim=1)


def train(x, y, classes, args, seed):
    """x: N×C×L normalised float32, y: N int64. Returns the trained network (eval mode)."""
    rng = np.random.default_rng(seed)
    torch.manual_seed(seed)
    n = len(y)
    order = rng.permutation(n)
    held = order[: max(1, n // 10)] if n >= 20 else order[:0]
    fit = order[len(held):]
    net = Dcnn(x.shape[1], x.shape[2], classes, conv1=args.conv1, kernel1=args.kernel1, conv2=args.conv2,
               kernel2=args.kernel2, hidden=args.hidden, dropout=args.dropout)
    opt = torch.optim.Adam(net.parameters(), lr=args.lr)
    # Class weights: balanced accuracy is what Athlos reports.
    counts = np.bincount(y[fit], minlength=classes).astype(np.float32)
    weights = torch.tensor(np.where(counts > 0, counts.sum() / np.maximum(counts, 1) / classes, 0.0), dtype=torch.float32)
    loss_fn = nn.CrossEntropyLoss(weight=weights)
    xt = torch.from_numpy(x[:, :, None, :])
    yt = torch.from_numpy(y)
    best, best_state, patience = float("inf"), None, 0
    for epoch in range(args.epochs):
        net.train()
        perm = torch.from_numpy(rng.permutation(fit))
        for i in range(0, len(perm), args.batch):
            idx = perm[i:i + args.batch]
            xb = xt[idx] + args.noise * torch.randn_like(xt[idx])
            opt.zero_grad()
            loss = loss_fn(net(xb), yt[idx])
            loss.backward()
            opt.step()
        if len(held) == 0:
            continue
        net.eval()
        with torch.no_grad():
            val = loss_fn(net(xt[held]), yt[held]).item()
        if val < best - 1e-4:
            best, best_state, patience = val, {k: v.clone() for k, v in net.state_dict().items()}, 0
        else:
            patience += 1
            if patience >= args.patience:
                break
    if best_state is not None:
        net.load_state_dict(best_state)
    return net.eval()


def predict(net, x):
    with torch.no_grad():
        return net(torch.from_numpy(x[:, :, None, :])).argmax(dim=1).numpy()


def balanced_accuracy(truth, predicted, classes):
    recalls = [np.mean(predicted[truth == c] == c) for c in range(classes) if np.any(truth == c)]
    return float(np.mean(recalls)) if recalls else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("windows", help="directory written by athlos train --export-windows")
    ap.add_argument("--out", required=True, help="ONNX file to write (the description goes beside it, .json)")
    ap.add_argument("--epochs", type=int, default=200)
    ap.add_argument("--batch", type=int, default=200)
    ap.add_argument("--lr", type=float, default=1e-3)
    ap.add_argument("--dropout", type=float, default=0.7)
    ap.add_argument("--noise", type=float, default=0.1, help="input noise SD in normalised units (thesis: 4.5 m/s²)")
    ap.add_argument("--patience", type=int, default=20, help="early stopping: epochs without improvement")
    ap.add_argument("--cv", type=int, default=0, help="leave-subjects-out cross-validation with K folds (0: none)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--conv1", type=int, default=8, help="filters of the first convolution (thesis: 8)")
    ap.add_argument("--kernel1", type=int, default=32, help="its kernel length (thesis: 32)")
    ap.add_argument("--conv2", type=int, default=16, help="filters of the second convolution (thesis: 16)")
    ap.add_argument("--kernel2", type=int, default=16, help="its kernel length (thesis: 16)")
    ap.add_argument("--hidden", type=int, default=64, help="units of the two fully connected layers (thesis: 64)")
    ap.add_argument("--reference", type=int, default=0,
                    help="store this many raw windows and their PyTorch probabilities in <out>.reference.json "
                         "(for tests comparing OpenCV dnn with PyTorch)")
    args = ap.parse_args()

    meta = json.load(open(os.path.join(args.windows, "meta.json")))
    if meta.get("format") != "athlos-windows-1":
        sys.exit(f"{args.windows}/meta.json: not an Athlos window export")
    x = np.load(os.path.join(args.windows, "windows.npy")).astype(np.float32)
    y = np.load(os.path.join(args.windows, "labels.npy")).astype(np.int64)
    groups = np.load(os.path.join(args.windows, "groups.npy"))
    classes = len(meta["classes"])
    mean = x.mean(axis=(0, 2))
    scale = x.std(axis=(0, 2))
    scale[scale < 1e-9] = 1.0
    normalise = lambda a: ((a - mean[None, :, None]) / scale[None, :, None]).astype(np.float32)
    xn = normalise(x)

    training = {"epochs": args.epochs, "batch": args.batch, "learning_rate": args.lr, "dropout": args.dropout,
                "noise": args.noise, "seed": args.seed, "windows": int(len(y)), "torch": torch.__version__}
    if args.cv > 1:
        subjects = np.unique(groups)
        folds = np.arange(len(subjects)) % args.cv
        fold_of = {s: f for s, f in zip(subjects, folds)}
        g = np.array([fold_of[s] for s in groups])
        predicted = np.zeros_like(y)
        for f in np.unique(g):
            test = g == f
            net = train(xn[~test], y[~test], classes, args, args.seed + int(f))
            predicted[test] = predict(net, xn[test])
        ba = balanced_accuracy(y, predicted, classes)
        confusion = np.zeros((classes, classes), dtype=int)
        for t, p in zip(y, predicted):
            confusion[t, p] += 1
        training["cross_validation"] = {"scheme": f"leave-subjects-out ({args.cv} folds)", "balanced_accuracy": ba,
                                        "accuracy": float(np.mean(predicted == y)), "confusion": confusion.tolist()}
        print(f"cross-validation ({args.cv} folds of subjects): balanced accuracy {ba:.3f}")

    net = train(xn, y, classes, args, args.seed)
    model = WithSoftmax(net).eval()
    c, length = x.shape[1], x.shape[2]
    torch.onnx.export(model, torch.zeros(1, c, 1, length), args.out, opset_version=11, input_names=["windows"],
                      output_names=["probabilities"],
                      dynamic_axes={"windows": {0: "n"}, "probabilities": {0: "n"}})
    description = {k: meta[k] for k in ("classes", "input_columns", "sensors", "units", "window", "step",
                                        "segmentation", "subjects")}
    description["format"] = "athlos-cnn-1"
    description["cnn"] = {"length": int(length), "mean": mean.tolist(), "scale": scale.tolist()}
    training["training_balanced_accuracy"] = balanced_accuracy(y, predict(net, xn), classes)
    description["training"] = training
    json_path = os.path.splitext(args.out)[0] + ".json"
    with open(json_path, "w") as f:
        json.dump(description, f, indent=1)
    if args.reference > 0:
        pick = np.random.default_rng(args.seed).choice(len(y), size=min(args.reference, len(y)), replace=False)
        with torch.no_grad():
            probabilities = model(torch.from_numpy(xn[pick][:, :, None, :])).numpy()
        with open(os.path.splitext(args.out)[0] + ".reference.json", "w") as f:
            json.dump({"windows": x[pick].tolist(), "labels": y[pick].tolist(),
                       "probabilities": probabilities.tolist()}, f)
    print(f"wrote {args.out} ({os.path.getsize(args.out)} bytes) and {json_path}; "
          f"balanced accuracy on the training windows {training['training_balanced_accuracy']:.3f}")


if __name__ == "__main__":
    main()
