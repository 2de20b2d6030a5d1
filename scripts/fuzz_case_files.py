#!/usr/bin/env python3
"""Fuzzes the case-file reader: mutates the case files in cases/ and runs `strandfem info` on each mutant.

Mutations: deleted keys, values of the wrong type, extreme and non-finite numbers, integers of 2^31 and beyond,
duplicated keys, truncation, garbage bytes, deleted or swapped lines. Each mutant is derived from (seed, index)
alone, so a run is reproducible and any mutant can be regenerated (--only INDEX --keep DIR writes it out).

A mutant fails the run when strandfem is killed by a signal, times out, exits with a code other than 0 or 2,
exits 2 without an "error:" message, prints info JSON with non-finite values (null where a number belongs), or
exits 0 although a mutation made the file invalid for sure (a duplicate key, a non-finite or out-of-range
number, a number replaced by text, an integer key of 2^31 or more, bytes that are not UTF-8 text).

    scripts/fuzz_case_files.py --binary build/apps/strandfem --count 300            # the CTest run
    scripts/fuzz_case_files.py --binary build/apps/strandfem --count 10000 --jobs 1  # the long run (docs/robustness.md)
"""
import argparse
import collections
import concurrent.futures
import json
import os
import pathlib
import random
import re
import subprocess
import sys
import tempfile
import time

import yaml

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Keys whose values are free-form (the program ignores them) or text.
FREE_FORM = {"expected", "description"}
# Integer keys and their smallest valid value (all have a maximum below 2^31).
INTEGER_KEYS = {"wires": 1, "elements_per_wire": 1, "elements": 1, "node": 0, "increments": 1, "max_iterations": 1,
                "max_cutbacks": 0, "line_search_cuts": 0, "threads": 0, "krylov_iterations": 0, "every": 1,
                "contacts_every": 1, "line_points": 1}
# Bytes that make a file invalid UTF-8 text for sure: C0 controls other than tab/LF/CR, DEL, lone continuation
# bytes, bytes that never start a UTF-8 sequence.
BAD_BYTES = [b for b in range(0x00, 0x20) if b not in (0x09, 0x0A, 0x0D)] + [0x7F] + list(range(0x80, 0xC0)) + [0xC0, 0xC1] + list(range(0xF5, 0x100))
NULLABLE_INFO_KEYS = {"lateral_clearance_mm", "radial_overlap_mm", "lay_ratio", "conductor"}  # null for the core; for a strand of its own layers


class DuplicateKeyLoader(yaml.SafeLoader):
    """A loader that reports duplicate mapping keys (PyYAML, like yaml-cpp, keeps one silently)."""


class DuplicateKey(Exception):
    pass


def _mapping_without_duplicates(loader, node, deep=False):
    keys = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        try:
            if key in keys:
                raise DuplicateKey(str(key))
            keys.add(key)
        except TypeError:  # unhashable key (a list): the program refuses those too
            raise DuplicateKey("unhashable")
    return yaml.SafeLoader.construct_mapping(loader, node, deep)


DuplicateKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _mapping_without_duplicates)


def has_duplicate_keys(text):
    try:
        yaml.load(text, Loader=DuplicateKeyLoader)
    except DuplicateKey:
        return True
    except Exception:
        return False
    return False


def leaves(node, path=()):
    """Every (path, value) in the tree, inner nodes included."""
    yield path, node
    if isinstance(node, dict):
        for k, v in node.items():
            yield from leaves(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, path + (i,))


def get_parent(tree, path):
    node = tree
    for p in path[:-1]:
        node = node[p]
    return node


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def free_form(path):
    return any(p in FREE_FORM or p in ("title", "name") for p in path if isinstance(p, str))


def integer_key(path):
    last = [p for p in path if isinstance(p, str)]
    return last[-1] if last and last[-1] in INTEGER_KEYS and isinstance(path[-1], str) else None


def mutate_tree(tree, rng):
    """One mutation of the parsed case; returns (kind, surely_invalid)."""
    paths = [(p, v) for p, v in leaves(tree) if p]
    path, value = rng.choice(paths)
    parent = get_parent(tree, path)
    key = path[-1]
    numeric = is_number(value) and not free_form(path)
    choice = rng.random()
    if choice < 0.15:
        del parent[key]
        return "delete", False
    if choice < 0.45 and is_number(value):
        int_key = integer_key(path) if not free_form(path) else None
        candidates = [
            ("nan", float("nan"), True), ("inf", float("inf"), True), ("-inf", float("-inf"), True),
            ("1e300", 1e300, True), ("-1e300", -1e300, True), ("1e16", 1e16, True), ("1e-300", 1e-300, False),
            ("5e-324", 5e-324, False), ("zero", 0, False), ("minus_one", -1, False), ("negated", -value, False),
            ("times_10", value * 10, False), ("divided_10", value / 10, False), ("times_1000", value * 1000, False),
            ("2^31-1", 2**31 - 1, False), ("2^31", 2**31, int_key is not None), ("2^32+1", 2**32 + 1, int_key is not None),
            ("2^63", 2**63, int_key is not None), ("2^64+3", 2**64 + 3, int_key is not None),
            ("-2^31", -2**31, int_key is not None), ("1e30_int", 10**30, True), ("half", 1.5, int_key is not None),
        ]
        name, new, invalid = rng.choice(candidates)
        parent[key] = new
        return "number:" + name, invalid and numeric
    if choice < 0.75:
        name, new = rng.choice([("text", "abc"), ("list", [1, 2]), ("mapping", {"a": 1}), ("null", None), ("bool", True),
                                ("empty_text", ""), ("long_text", "x" * 5000)])
        parent[key] = new
        return "type:" + name, numeric  # a number key given anything but a number
    if choice < 0.85 and isinstance(parent, dict):
        parent[str(key) + "_typo"] = value  # an unknown key beside the original
        return "unknown_key", False
    if isinstance(value, list) and value:
        value.append(value[rng.randrange(len(value))])  # one item more (lists of fixed length, one per wire...)
        return "list_item", False
    if isinstance(value, dict) and value:
        value.clear()
        return "empty_mapping", False
    del parent[key]
    return "delete", False


def mutate_text(text, rng):
    """One mutation of the file's bytes; returns (data, kind, surely_invalid, destructive)."""
    data = text.encode("utf-8", "surrogateescape") if isinstance(text, str) else text
    lines = data.split(b"\n")
    choice = rng.random()
    if choice < 0.3:
        # Duplicate a key: a block-mapping line, or a pair inside a flow mapping.
        key_lines = [i for i, l in enumerate(lines) if re.match(rb"^\s*[A-Za-z_][A-Za-z0-9_]*:", l)]
        flow = [(i, m) for i, l in enumerate(lines) for m in re.finditer(rb"([{,]\s*)([A-Za-z_][A-Za-z0-9_]*): ([^,{}\[\]]+)", l)]
        if flow and (rng.random() < 0.5 or not key_lines):
            i, m = rng.choice(flow)
            value = m.group(3) if rng.random() < 0.5 else b"-5"
            insert = b", " + m.group(2) + b": " + value
            l = lines[i]
            lines[i] = l[: m.end()] + insert + l[m.end():]
        elif key_lines:
            i = rng.choice(key_lines)
            copy = lines[i] if rng.random() < 0.5 else re.sub(rb":.*$", b": -5", lines[i])
            lines.insert(i + 1, copy)
        out = b"\n".join(lines)
        return out, "duplicate_key", has_duplicate_keys(out.decode("utf-8", "replace")), False
    if choice < 0.45:
        cut = rng.randrange(len(data) + 1)
        return data[:cut], "truncate", False, True
    if choice < 0.65:
        at = rng.randrange(len(data) + 1)
        garbage = bytes([rng.choice(BAD_BYTES)]) + bytes(rng.randrange(256) for _ in range(rng.randrange(8)))
        return data[:at] + garbage + data[at:], "garbage_bytes", True, False
    if choice < 0.75 and len(lines) > 1:
        i = rng.randrange(len(lines))
        del lines[i]
        return b"\n".join(lines), "delete_line", False, True
    if choice < 0.85 and len(lines) > 1:
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        return b"\n".join(lines), "swap_lines", False, True
    i = rng.randrange(len(lines))
    lines[i] = (b"  " + lines[i]) if rng.random() < 0.5 else lines[i].lstrip()
    return b"\n".join(lines), "indent", False, True


def make_mutant(bases, seed, index):
    rng = random.Random(f"{seed}-{index}")
    name, text, tree = rng.choice(bases)
    kinds, invalid, destructive = [], False, False
    data = text.encode("utf-8")
    if tree is not None and rng.random() < 0.6:
        tree = json.loads(json.dumps(tree))  # deep copy
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            kind, sure = mutate_tree(tree, rng)
            kinds.append(kind)
            invalid = invalid or sure
        data = yaml.safe_dump(tree, sort_keys=False, allow_unicode=True).encode("utf-8")
    if not kinds or rng.random() < 0.4:
        for _ in range(rng.choice([1, 1, 2])):
            data, kind, sure, cuts = mutate_text(data, rng)
            kinds.append(kind)
            destructive = destructive or cuts
            invalid = (invalid and not cuts) or sure
    return name, data, kinds, invalid


def nulls(value, key=None):
    """Keys of null values in info JSON that should hold numbers."""
    if value is None:
        return [] if key in NULLABLE_INFO_KEYS else [key]
    if isinstance(value, dict):
        return [k for kk, v in value.items() for k in nulls(v, kk)]
    if isinstance(value, list):
        return [k for v in value for k in nulls(v, key)]
    return []


def run_one(binary, directory, seed, index, bases, timeout):
    name, data, kinds, invalid = make_mutant(bases, seed, index)
    path = os.path.join(directory, f"mutant_{index}.yaml")
    with open(path, "wb") as f:
        f.write(data)
    start = time.monotonic()
    try:
        p = subprocess.run([binary, "info", path], capture_output=True, timeout=timeout)
        code, out, err = p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        code, out, err = "timeout", b"", ""
    elapsed = time.monotonic() - start
    problem = None
    if code == "timeout":
        problem = f"timed out after {timeout} s"
    elif code < 0:
        problem = f"killed by signal {-code}"
    elif code not in (0, 2):
        problem = f"exit code {code}"
    elif code == 2 and "error:" not in err:
        problem = "exit 2 without an error message"
    elif code == 0 and invalid:
        problem = "exit 0 on a mutant that is invalid for sure"
    elif code == 0:
        try:
            bad = nulls(json.loads(out))
            if bad:
                problem = "info has non-finite values: " + ", ".join(map(str, bad[:5]))
        except ValueError:
            problem = "exit 0 without JSON on stdout"
    os.remove(path)
    return index, name, kinds, code, elapsed, problem, err[-600:], data


def load_bases(cases):
    bases = []
    for f in sorted(pathlib.Path(cases).rglob("*.yaml")):
        text = f.read_text(encoding="utf-8")
        bases.append((str(f.relative_to(ROOT) if f.is_relative_to(ROOT) else f), text, yaml.safe_load(text)))
    return bases


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=str(ROOT / "build/apps/strandfem"))
    parser.add_argument("--cases", default=str(ROOT / "cases"))
    parser.add_argument("--count", type=int, default=300)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per mutant")
    parser.add_argument("--only", type=int, help="run only this mutant index")
    parser.add_argument("--keep", help="folder for failing mutants (and --only's mutant)")
    args = parser.parse_args()

    bases = load_bases(args.cases)
    indices = [args.only] if args.only is not None else list(range(args.count))
    codes, kinds_seen, failures = collections.Counter(), collections.Counter(), []
    slowest = (0.0, None)
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="strandfem_fuzz_") as directory, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_one, args.binary, directory, args.seed, i, bases, args.timeout) for i in indices]
        for future in concurrent.futures.as_completed(futures):
            index, name, kinds, code, elapsed, problem, err, data = future.result()
            codes[str(code)] += 1
            for k in kinds:
                kinds_seen[k.split(":")[0]] += 1
            slowest = max(slowest, (elapsed, index))
            if problem or args.only is not None:
                if args.keep:
                    os.makedirs(args.keep, exist_ok=True)
                    with open(os.path.join(args.keep, f"mutant_{index}.yaml"), "wb") as f:
                        f.write(data)
            if problem:
                failures.append((index, name, kinds, problem, err))
    wall = time.monotonic() - start
    print(f"mutants: {len(indices)} (seed {args.seed}, {len(bases)} base cases), {wall:.1f} s wall, jobs {args.jobs}")
    print("exit codes: " + ", ".join(f"{c}: {n}" for c, n in sorted(codes.items())))
    print("mutations: " + ", ".join(f"{k}: {n}" for k, n in sorted(kinds_seen.items())))
    print(f"slowest mutant: {slowest[0]:.2f} s (index {slowest[1]})")
    for index, name, kinds, problem, err in sorted(failures)[:50]:
        print(f"FAIL mutant {index} of {name} ({', '.join(kinds)}): {problem}\n  {err.strip()[-300:]}")
    print(f"failures: {len(failures)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
