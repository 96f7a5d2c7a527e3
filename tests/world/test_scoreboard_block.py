"""Scoreboard.block (Emulator.score_block): many scores in one read, 0 where a score is unset."""
from emulator.world.state import Scoreboard


def test_block_reads_each_score_and_zero_where_none_is_set():
    board = Scoreboard()
    board.add_objective("a")
    board.add_objective("b")
    board.set("x", "a", 5)
    board.set("y", "b", -7)
    board.add_objective("gone")
    board.set("x", "gone", 9)
    board.remove_objective("gone")
    block = board.block(["x", "y", "nobody"], ["a", "b", "gone", "unknown"])
    assert block.tolist() == [[5, 0, 0, 0], [0, -7, 0, 0], [0, 0, 0, 0]]
    assert [[board.get(h, o) or 0 for o in ("a", "b", "gone", "unknown")] for h in ("x", "y", "nobody")] == block.tolist()


def test_a_reader_reads_the_block_as_it_is_when_called():
    board = Scoreboard()
    board.add_objective("a")
    board.set("x", "a", 5)
    read = board.reader(["x", "later"], ["a", "b"])
    assert read().tolist() == board.block(["x", "later"], ["a", "b"]).tolist() == [[5, 0], [0, 0]]
    board.add_objective("b")
    board.set("later", "b", -3)
    board.set("x", "a", 6)
    assert read().tolist() == [[6, 0], [0, -3]]
    for i in range(200):  # the arrays grow: the reader finds the scores where they went
        board.set(f"h{i}", "b", i)
    board.reset("x", "a")
    assert read().tolist() == [[0, 0], [0, -3]]
    board.set("x", "a", 7)
    board.remove_objective("b")
    assert read().tolist() == board.block(["x", "later"], ["a", "b"]).tolist() == [[7, 0], [0, 0]]
    assert read().dtype == board.block(["x"], ["a"]).dtype
