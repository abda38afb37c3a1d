"""The one runner of every benchmark: a list of self-contained tasks mapped
through a function, in worker processes, on a dask.distributed cluster or in
this process, with a progress bar.

A task is any picklable value (a frozen dataclass in practice: a BARN run, a
dynamic-field run, an experiment's trial, a figure job) and the function runs
it in whatever process receives it, so a result depends only on its task,
never on where it ran.
"""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Callable, Optional, Sequence

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import short_repr

EXECUTORS = ("local", "dask", "serial")
DEFAULT_WORKERS = 2
SCHEDULER_TIMEOUT = 10.0  # s to reach a dask scheduler before the run is refused


def run_tasks(tasks: Sequence, runner: Callable, executor: str = "local", scheduler: Optional[str] = None,
              workers: int = DEFAULT_WORKERS, progress: bool = True, label: str = "trials",
              check_task: Optional[Callable] = None) -> list:
    """``runner(task)`` of every task, returned in the tasks' order.

    executor "local": a ProcessPoolExecutor of ``workers`` processes; "dask": a
    dask.distributed Client at ``scheduler``, or a LocalCluster of ``workers``
    single-threaded processes when no address is given; "serial": one after
    another in this process. A progress bar (tqdm, on stderr) labelled
    ``label`` counts the tasks. ``check_task(task)``, when given, raises
    FgdwaError for a task that cannot be sent to another process; it is called
    for every task unless the executor is "serial"."""
    if executor not in EXECUTORS:
        raise FgdwaError(f"executor = {short_repr(executor)}: expected one of {', '.join(EXECUTORS)}")
    if scheduler is not None and executor != "dask":
        raise FgdwaError(f"scheduler = {short_repr(scheduler)}: only the dask executor takes a scheduler address")
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise FgdwaError(f"workers = {short_repr(workers)}: must be an integer >= 1")
    tasks = list(tasks)
    if executor != "serial" and check_task is not None:
        for task in tasks:
            check_task(task)
    from tqdm import tqdm

    results = [None] * len(tasks)
    with tqdm(total=len(tasks), desc=label, unit="run", disable=not progress, leave=False,
              dynamic_ncols=True) as bar:
        if executor == "serial":
            for i, task in enumerate(tasks):
                results[i] = runner(task)
                bar.update()
        elif executor == "local":
            with ProcessPoolExecutor(max_workers=int(workers)) as pool:
                futures = {pool.submit(runner, task): i for i, task in enumerate(tasks)}
                for future in as_completed(futures):
                    results[futures[future]] = future.result()
                    bar.update()
        else:
            _run_dask(tasks, scheduler, int(workers), bar, results, runner)
    return results


def _run_dask(tasks, scheduler, workers, bar, results, runner) -> None:
    try:
        from dask.distributed import Client, LocalCluster
        from dask.distributed import as_completed as dask_completed
    except ImportError as error:  # pragma: no cover - dask is a dependency
        raise FgdwaError(f"executor 'dask' needs dask[distributed]: {error}") from error
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        try:
            client = Client(scheduler, timeout=SCHEDULER_TIMEOUT)
        except Exception as error:  # noqa: BLE001 - dask raises OSError, TimeoutError, ValueError and more here
            raise FgdwaError(f"scheduler = {short_repr(scheduler)}: no dask scheduler answered within {SCHEDULER_TIMEOUT:g} s "
                             f"({type(error).__name__}: {str(error)[:200]}); start one with `dask scheduler` "
                             f"and workers with `dask worker ADDRESS`, or leave --scheduler out for a local "
                             f"cluster") from None
    try:
        futures = client.map(runner, tasks, pure=False)
        index = {future.key: i for i, future in enumerate(futures)}
        for future in dask_completed(futures):
            results[index[future.key]] = future.result()
            bar.update()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
