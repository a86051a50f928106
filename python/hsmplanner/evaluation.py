"""High Speed Performance of a toolpath, from its feed-rate simulation (guidance-curve paper §2.3).

Beyond times and feed classes: tool entries and exits (each machining sequence is a run of cutting blocks
between two rapids), the share of short sequences and, from the generator, the share of short passes (the
paper's "short length machining sequences … of the total number of trajectories"). Our threshold for
"short" is 20 mm (five diameters of the paper's 4 mm ball): the paper gives none.
"""
import numpy as np

from . import feedsim

SHORT_SEQUENCE_MM = 20.0


def machining_sequences(blocks):
    """Lengths (mm) of the runs of cutting blocks between rapids."""
    cutting = np.asarray(blocks["motion"]) != 0
    lengths, current, inside = [], 0.0, False
    for cut, length in zip(cutting, blocks["length"]):
        if cut:
            current += length
            inside = True
        elif inside:
            lengths.append(current)
            current, inside = 0.0, False
    if inside:
        lengths.append(current)
    return np.asarray(lengths)


def evaluate(result, short_sequence_mm=SHORT_SEQUENCE_MM):
    """A dict of the performance figures of a simulation kept with blocks=True."""
    blocks = result.blocks
    if len(blocks["line"]) == 0:
        raise ValueError("the simulation holds no blocks: simulate with blocks=True to evaluate it")
    summary = result.summary
    sequences = machining_sequences(blocks)
    short = int(np.sum(sequences < short_sequence_mm))
    return {
        "machining_time_s": summary.total_time,
        "cutting_time_s": summary.cutting_time,
        "naive_time_s": summary.naive_time,
        "time_over_naive": summary.time_over_naive,
        "path_length_mm": summary.cutting_length,
        "blocks": summary.block_count,
        "cutting_blocks": summary.cutting_blocks,
        "tool_entries": int(len(sequences)),
        "tool_exits": int(len(sequences)),
        "short_sequences": short,
        "short_sequence_share": short / len(sequences) if len(sequences) else 0.0,
        "short_sequence_threshold_mm": short_sequence_mm,
        "feed_classes_time": list(summary.feed_classes_time),
        "feed_classes_blocks": list(summary.feed_classes_blocks),
        "block_length_classes": list(summary.length_classes),
        "block_length_edges_mm": list(feedsim.LENGTH_CLASS_EDGES_MM),
    }


def short_share(lengths, short_mm=SHORT_SEQUENCE_MM):
    """Share of the lengths (of passes or sequences) under `short_mm`."""
    lengths = np.asarray(list(lengths), dtype=float)
    return float(np.mean(lengths < short_mm)) if len(lengths) else 0.0
