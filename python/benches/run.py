"""Times `cardan.run` on the shipped 7200-step pump case (two mechanisms, gas), from its TOML
text, with and without the per-step columns: the same work as the Rust benchmark
`case_text_pump_7200_steps_two_mechanisms_in_memory_{steps,summary}` (runner/benches/runner.rs,
`cargo bench -p cardan-runner --bench runner -- in_memory`). Prints the best and the median of
REPEATS runs, in ms. Run it on a quiet machine.

    python run.py [REPEATS]
"""

import os
import statistics
import sys
import time

import cardan

CASE = os.path.join(
    os.path.dirname(__file__), "..", "..", "configs", "karhula-pump-r60-l140-a0-w30pi.toml"
)


def main(repeats=30):
    repeats = int(repeats)
    with open(CASE) as f:
        text = f.read()
    for steps in (True, False):
        cardan.run(text, steps=steps)  # warm-up
        times = []
        for _ in range(repeats):
            start = time.perf_counter()
            cardan.run(text, steps=steps)
            times.append(time.perf_counter() - start)
        label = "in_memory_steps" if steps else "in_memory_summary"
        print(
            f"cardan.run {label}: best {1000 * min(times):.2f} ms, "
            f"median {1000 * statistics.median(times):.2f} ms ({repeats} runs)"
        )


if __name__ == "__main__":
    main(*sys.argv[1:])
