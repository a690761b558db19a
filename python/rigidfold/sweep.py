"""Sweeps: many independent rigidfold computations at once, on Dask distributed.

    import rigidfold
    records = rigidfold.sweep(tasks, client=None, out="results.jsonl")

    python3 -m rigidfold.sweep SPEC.json --out RESULTS.jsonl [--scheduler ADDRESS] [--workers N]

A task is a dict with a "kind" and its parameters (KINDS below). Without a client, the sweep
starts a LocalCluster of this machine's cores (one single-threaded process each: the kernel holds
no lock, and a process keeps one task's memory from another's); with one, it runs on whatever
cluster the client reaches (`dask-scheduler` and `dask-worker` on other machines, each with
rigidfold installed).

Results do not depend on how many workers there are: every task is a pure function of its
parameters, timings (`seconds`) are dropped, and the records come back in task order. With `out`,
each finished task is appended to the JSON-lines file once, as it finishes; a rerun with the same
file reads it first and runs only the tasks missing from it (a line cut short by a kill is
dropped and its task run again). A worker that dies mid-task loses nothing: Dask runs the task
again on another worker.

Splitting an enumeration: `assignment_tasks` splits `enumerate_assignments` into the subtrees of
its search (`assignment_branches`); `merge_assignments` joins their records into the whole
search's result, the classes in the serial search's order.
"""
import argparse
import glob
import hashlib
import itertools
import json
import math
import os
import sys
import time
import types

import numpy as np

KIND_PARAMETERS = {
    # kind: (required parameters, optional parameters)
    "check": ({"pattern"}, {"letters", "explore_branches", "force_general", "coordinate_tolerance"}),
    "assignments": ({"pattern"}, {"branch", "symmetry", "max_verdicts", "max_assignments"}),
    "waterbomb": ({"n", "theta0"}, {"k_m", "k_v"}),
    "metamaterial": ({"theta"}, {"alpha", "a", "b", "c"}),
    "string": ({"points"}, {"theta0", "roll"}),
    "repair": ({"pattern"}, {"keep_boundary", "max_move", "use_letters"}),
}
GENERATORS = ("miura_ori", "square_twist", "waterbomb_base", "corrugated_unit")


class SweepError(ValueError):
    """A task or spec that cannot run, naming the place (the CLI exits 2 with it)."""


class SweepResults(list):
    """The records in task order, and what this call did: ran (tasks run now), reused (read
    from `out`), seconds, workers."""
    ran = 0
    reused = 0
    seconds = 0.0
    workers = 0


# ----------------------------------------------------------------------------------------------
# tasks

def validate(task, place="task"):
    """The task as a plain dict (JSON types only), its kind and parameters checked."""
    if not isinstance(task, dict):
        raise SweepError(f"{place}: a task is an object with a \"kind\", not {type(task).__name__}")
    kind = task.get("kind")
    if kind not in KIND_PARAMETERS:
        raise SweepError(f"{place}.kind: {kind!r}: one of {', '.join(sorted(KIND_PARAMETERS))}")
    required, optional = KIND_PARAMETERS[kind]
    missing = required - task.keys()
    if missing:
        raise SweepError(f"{place}: {kind} needs {', '.join(sorted(missing))}")
    unknown = task.keys() - required - optional - {"kind"}
    if unknown:
        raise SweepError(f"{place}: {kind} takes no {', '.join(sorted(unknown))} "
                         f"(it takes {', '.join(sorted(required | optional))})")
    if "pattern" in task:
        pattern_spec(task["pattern"], f"{place}.pattern")
    try:
        return json.loads(json.dumps(task, allow_nan=False))
    except (TypeError, ValueError) as e:
        raise SweepError(f"{place}: not JSON data ({e})") from None


def pattern_spec(spec, place):
    if isinstance(spec, str):
        return
    if isinstance(spec, dict) and len(spec.keys() & {"generator", "bundled"}) == 1:
        if "generator" in spec and spec["generator"] not in GENERATORS:
            raise SweepError(f"{place}.generator: {spec['generator']!r}: one of {', '.join(GENERATORS)}")
        return
    raise SweepError(f"{place}: a FOLD/SVG/OPX path, {{\"generator\": NAME, ...parameters}} or {{\"bundled\": NAME}}")


def task_id(task):
    """A name of the task's content: the same task has the same id in every run."""
    text = json.dumps(task, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:20]


def load_pattern(spec):
    import rigidfold
    if isinstance(spec, str):
        return rigidfold.load(spec)
    if "bundled" in spec:
        examples = rigidfold.bundled_examples()
        if spec["bundled"] not in examples:
            raise SweepError(f"pattern.bundled: {spec['bundled']!r}: one of {', '.join(sorted(examples))}")
        return examples[spec["bundled"]]
    args = {k: v for k, v in spec.items() if k != "generator"}
    return getattr(rigidfold, spec["generator"])(**args)


def plain(value):
    """JSON data: numpy arrays as lists, non-finite numbers as null, timings dropped."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items() if k != "seconds" and not str(k).endswith("_seconds")}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, np.generic):
        return plain(value.item())
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if hasattr(value, "vertices") and hasattr(value, "edges"):  # a CreasePattern: its FOLD text
        import rigidfold
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "pattern.fold")
            rigidfold.save(value, path)
            with open(path, encoding="utf-8") as f:
                return json.load(f)
    return value


def run_task(task):
    """One task, on a worker: {"result": ...}, or {"error": {"type", "message"}} when its input
    is refused (InputError, ValueError, NoAnswerError; TypeError: a generator's parameters that
    it does not take), so that one bad task does not stop the sweep."""
    import rigidfold
    try:
        return {"result": plain(compute(rigidfold, task))}
    except (ValueError, RuntimeError, TypeError) as e:  # InputError is a ValueError; NoAnswerError a RuntimeError
        return {"error": {"type": type(e).__name__, "message": str(e)}}


def compute(rigidfold, task):
    kind = task["kind"]
    get = task.get
    if kind == "check":
        return rigidfold.check(load_pattern(task["pattern"]), use_assignment=get("letters", True),
                               explore_branches=get("explore_branches", False), force_general=get("force_general", False),
                               coordinate_tolerance=get("coordinate_tolerance"), source=source_of(task["pattern"]))
    if kind == "assignments":
        return rigidfold.enumerate_assignments(load_pattern(task["pattern"]), symmetry=get("symmetry", True),
                                               max_assignments=get("max_assignments", 50_000_000),
                                               max_verdicts=get("max_verdicts", 100_000), max_listed=2**31 - 1,
                                               branch=get("branch", []), source=source_of(task["pattern"]))
    if kind == "waterbomb":
        return rigidfold.waterbomb_bistability(task["n"], task["theta0"], get("k_m", 1.0), get("k_v", 1.0))
    if kind == "metamaterial":
        return rigidfold.square_twist_unit(task["theta"], **{k: task[k] for k in ("alpha", "a", "b", "c") if k in task})
    if kind == "string":
        return rigidfold.design_string_from_curve(np.asarray(task["points"], dtype=float), theta0=get("theta0"),
                                                  roll=get("roll"))
    if kind == "repair":
        return rigidfold.repair(load_pattern(task["pattern"]), keep_boundary=get("keep_boundary", False),
                                max_move=get("max_move"), use_letters=get("use_letters", True))
    raise SweepError(f"kind {kind!r}")


def source_of(spec):
    return spec if isinstance(spec, str) else json.dumps(spec, sort_keys=True)


# ----------------------------------------------------------------------------------------------
# assignment enumeration split by search prefix

def assignment_tasks(pattern, depth=None, tasks_wanted=64, **options):
    """`enumerate_assignments` of `pattern` (a pattern spec: path, generator or bundled) as
    tasks, one per subtree of its search at `depth` vertices (None: the least depth with at
    least `tasks_wanted` subtrees). options: symmetry, max_verdicts, max_assignments."""
    import rigidfold
    loaded = load_pattern(pattern)
    symmetry = options.get("symmetry", True)
    if depth is None:
        depth, branches = 0, [[]]
        while len(branches) < tasks_wanted:
            deeper = rigidfold.assignment_branches(loaded, depth + 1, symmetry)
            if not deeper or len(deeper[0]) <= depth:
                break  # the search has no more vertices (a deeper level may keep the count: one letter set fits)
            depth, branches = depth + 1, deeper
    else:
        branches = rigidfold.assignment_branches(loaded, depth, symmetry)
    return [validate({"kind": "assignments", "pattern": pattern, "branch": list(b), **options}) for b in branches]


def merge_assignments(records):
    """The records of one enumeration's subtrees (assignment_tasks), in task order, joined into
    the result of the whole search (the keys of `rigidfold assignments --json`): counts added,
    the classes listed in the serial search's order, `branch` [] and no `seconds`."""
    errors = [r for r in records if "error" in r]
    if errors:
        raise SweepError(f"merge_assignments: {len(errors)} subtree(s) failed: {errors[0]['error']['message']}")
    results = [r["result"] for r in records]
    if not results:
        raise SweepError("merge_assignments: no records")
    merged = dict(results[0], branch=[])
    for key in ("search_steps", "assignments", "classes_reached", "classes_with_verdict", "foldable_classes",
                "not_foldable_classes", "undecided_classes"):
        merged[key] = sum(r[key] for r in results)
    merged["complete"] = all(r["complete"] for r in results)
    merged["classes"] = merged["classes_reached"] if merged["complete"] else None
    merged["listed"] = [c for r in results for c in r["listed"]]
    merged.pop("seconds", None)
    orbits = sum(c["orbit_size"] for c in merged["listed"])
    if merged["complete"] and orbits != merged["assignments"]:
        raise SweepError(f"merge_assignments: the class orbits add up to {orbits}, not to the "
                         f"{merged['assignments']} assignments (subtrees missing or of two searches)")
    return merged


# ----------------------------------------------------------------------------------------------
# the results file

def read_done(out):
    """Records already in `out`, by id. A last line cut short (a kill mid-write) is cut off,
    once every whole line has been read as a record."""
    done = {}
    if not os.path.exists(out):
        return done
    try:
        with open(out, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SweepError(f"{out}: {e.strerror}") from None
    end = data.rfind(b"\n") + 1
    for number, line in enumerate(data[:end].splitlines(), 1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
            done[record["id"]] = record
        except (ValueError, KeyError, TypeError):
            raise SweepError(f"{out}: line {number}: not a record of a rigidfold sweep") from None
    if end != len(data):
        with open(out, "rb+") as f:
            f.truncate(end)
    return done


def sweep(tasks, client=None, out=None, progress=False, workers=None):
    """Runs every task (dicts, KIND_PARAMETERS) and returns their records in task order:
    {"id", "task", "result"} or {"id", "task", "error"}. client: a dask.distributed Client (None:
    a LocalCluster of `workers` processes, default this machine's cores, closed at the end).
    out: a JSON-lines file each finished record is appended to; tasks recorded there are not run
    again. progress: a line on stderr per twentieth of the tasks, with the time left."""
    start = time.monotonic()
    tasks = [validate(t, f"tasks[{i}]") for i, t in enumerate(tasks)]
    ids = [task_id(t) for t in tasks]
    done = read_done(out) if out else {}
    todo = {}
    for i, t in zip(ids, tasks):
        if i not in done:
            todo.setdefault(i, t)
    results = SweepResults()
    results.reused = len(set(ids) & done.keys())
    if todo:
        try:
            sink = open(out, "a", encoding="utf-8") if out else None
        except OSError as e:
            raise SweepError(f"{out}: {e.strerror}") from None
        own = client is None
        cluster = None
        if own:
            from distributed import Client, LocalCluster
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
            client = Client(cluster)
        try:
            results.workers = len(client.scheduler_info().get("workers", {}))
            run_on(client, todo, done, sink, progress)
        finally:
            if sink:
                sink.close()
            if own:
                client.close()
                cluster.close()
    results.ran = len(todo)
    results.extend(done[i] for i in ids)
    results.seconds = time.monotonic() - start
    return results


def run_on(client, todo, done, sink, progress):
    from distributed import as_completed
    keys = list(todo)
    futures = client.map(run_task, [todo[k] for k in keys], key=[f"rigidfold-{k}" for k in keys], pure=True)
    by_key = {f.key: k for f, k in zip(futures, keys)}
    step = max(1, len(keys) // 20)
    start = time.monotonic()
    for finished, (future, outcome) in enumerate(as_completed(futures, with_results=True), 1):
        key = by_key[future.key]
        record = {"id": key, "task": todo[key], **outcome}
        done[key] = record
        if sink:
            sink.write(json.dumps(record, sort_keys=True, allow_nan=False) + "\n")
            sink.flush()
        if progress and (finished % step == 0 or finished == len(keys)):
            elapsed = time.monotonic() - start
            left = elapsed / finished * (len(keys) - finished)
            print(f"sweep: {finished}/{len(keys)} tasks, {elapsed:.1f} s, about {left:.0f} s left",
                  file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------------------------
# the command line

def expand(entry, place, base):
    """A spec entry as tasks: "grid" (parameter -> list, or {"from", "to", "num"}: evenly spaced,
    ends included) gives one task per point; "patterns" (a glob, relative to the spec's folder)
    one per file; an "assignments" entry with "split_depth" or "tasks" one per search subtree."""
    if not isinstance(entry, dict):
        raise SweepError(f"{place}: an object with a \"kind\"")
    entry = dict(entry)
    grid = entry.pop("grid", {})
    if not isinstance(grid, dict):
        raise SweepError(f"{place}.grid: an object of parameter -> values")
    axes = []
    for name, values in grid.items():
        if isinstance(values, dict):
            try:
                lo, hi, num = float(values["from"]), float(values["to"]), int(values["num"])
            except (KeyError, TypeError, ValueError):
                raise SweepError(f"{place}.grid.{name}: a list, or {{\"from\", \"to\", \"num\"}}") from None
            if num < 1 or not (math.isfinite(lo) and math.isfinite(hi)):
                raise SweepError(f"{place}.grid.{name}: num >= 1 and finite ends")
            values = np.linspace(lo, hi, num).tolist()
        if not isinstance(values, list) or not values:
            raise SweepError(f"{place}.grid.{name}: a non-empty list, or {{\"from\", \"to\", \"num\"}}")
        axes.append([(name, v) for v in values])
    if "patterns" in entry:
        pattern_glob = entry.pop("patterns")
        if not isinstance(pattern_glob, str):
            raise SweepError(f"{place}.patterns: a glob of pattern files")
        files = sorted(glob.glob(os.path.join(base, pattern_glob), recursive=True))
        if not files:
            raise SweepError(f"{place}.patterns: {pattern_glob!r} matches no file in {base}")
        axes.append([("pattern", f) for f in files])
    elif isinstance(entry.get("pattern"), str):
        entry["pattern"] = os.path.join(base, entry["pattern"])
    split = {k: entry.pop(k) for k in ("split_depth", "tasks") if k in entry}
    tasks = []
    for point in itertools.product(*axes):
        task = {**entry, **dict(point)}
        if split:
            if task.get("kind") != "assignments":
                raise SweepError(f"{place}: split_depth and tasks split an \"assignments\" task only")
            options = {k: v for k, v in task.items() if k not in ("kind", "pattern")}
            tasks += assignment_tasks(task.get("pattern"), split.get("split_depth"), split.get("tasks", 64), **options)
        else:
            tasks.append(validate(task, place))
    return tasks


def read_spec(path):
    try:
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
    except OSError as e:
        raise SweepError(f"{path}: {e.strerror}") from None
    except ValueError as e:
        raise SweepError(f"{path}: not JSON ({e})") from None
    if not isinstance(spec, dict) or not isinstance(spec.get("tasks"), list):
        raise SweepError(f"{path}: an object with \"tasks\": [...]")
    base = os.path.dirname(os.path.abspath(path))
    tasks = []
    for i, entry in enumerate(spec["tasks"]):
        tasks += expand(entry, f"{path}: tasks[{i}]", base)
    return tasks


def summary(records):
    lines = []
    by_kind = {}
    for r in records:
        by_kind.setdefault(r["task"]["kind"], []).append(r)
    for kind, rs in by_kind.items():
        failed = sum("error" in r for r in rs)
        lines.append(f"{kind}: {len(rs)} tasks, {len(rs) - failed} answered, {failed} refused their input")
        if kind == "assignments" and not failed:
            groups = {}
            for r in rs:
                key = json.dumps({k: v for k, v in r["task"].items() if k != "branch"}, sort_keys=True)
                groups.setdefault(key, []).append(r)
            for key, group in groups.items():
                m = merge_assignments(group)
                lines.append(f"  {json.loads(key)['pattern']}: {m['assignments']} assignments in "
                             f"{m['classes']} classes, {m['foldable_classes']} foldable "
                             f"({len(group)} subtrees)")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m rigidfold.sweep", description=__doc__.split("\n\n")[0])
    parser.add_argument("spec", help="JSON: {\"tasks\": [task or grid entry, ...]} (see docs/python.md)")
    parser.add_argument("--out", required=True, help="JSON-lines results; tasks already in it are not run again")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster here)")
    parser.add_argument("--workers", type=int, help="processes of the LocalCluster (default: this machine's cores)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    args = parser.parse_args(argv)
    try:
        if args.workers is not None and args.workers < 1:
            raise SweepError(f"--workers: {args.workers}: at least 1")
        tasks = read_spec(args.spec)
        client = None
        if args.scheduler:
            from distributed import Client
            try:
                client = Client(args.scheduler, timeout=30)
            except (OSError, TimeoutError) as e:
                raise SweepError(f"--scheduler: {args.scheduler}: {e}") from None
        try:
            records = sweep(tasks, client=client, out=args.out, progress=not args.quiet, workers=args.workers)
        finally:
            if client is not None:
                client.close()
    except SweepError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    print(f"{len(records)} tasks: {records.ran} run now on {records.workers} workers, {records.reused} read from "
          f"{args.out}; {records.seconds:.1f} s")
    print(summary(records))
    return 0


class _CallableModule(types.ModuleType):
    """`rigidfold.sweep(tasks, ...)` calls sweep(); `rigidfold.sweep.merge_assignments` etc. stay."""

    def __call__(self, *args, **kwargs):
        return sweep(*args, **kwargs)


if __name__ == "__main__":
    # The module's own copy, so that the functions sent to the workers are named
    # rigidfold.sweep.run_task, not __main__.run_task.
    from rigidfold.sweep import main as module_main
    sys.exit(module_main())
else:
    sys.modules[__name__].__class__ = _CallableModule
