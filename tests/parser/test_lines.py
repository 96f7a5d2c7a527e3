from mcfunction_parser import ast
from mcfunction_parser.parse import parse_function

PATH = "data/ns/function/f.mcfunction"


def parse(source: str, version=(1, 21, 0)):
    return parse_function(source, PATH, "ns:f", version)


def test_comments_blank_lines_and_indentation():
    fn, diags = parse("# header\n\n   say a\n\t# indented comment\nsay b # not a comment\n")
    assert not diags
    assert [c.message for c in fn.commands] == ["a", "b # not a comment"]
    assert (fn.commands[0].loc.line, fn.commands[0].loc.col) == (3, 4)
    assert fn.lines == 5 and fn.id == "ns:f" and fn.path == PATH


def test_every_error_is_reported_and_good_lines_kept():
    fn, diags = parse("say ok\nscoreboard players add @s x -1\nkill @e[limit=0]\nsay still ok\nbogus\n")
    assert [c.message for c in fn.commands if isinstance(c, ast.Say)] == ["ok", "still ok"]
    assert [(d.line, d.col) for d in diags] == [(2, 29), (3, 15), (5, 1)]
    text = diags[0].format()
    assert text.startswith(f"{PATH}:2:29: error: ") and text.endswith("\n" + " " * (4 + 28) + "^")


def test_continuation_joins_trimmed_lines():
    fn, diags = parse("execute as @a \\\n    at @s \\\n  run say hi\nsay next\n")
    assert not diags
    cmd = fn.commands[0]
    assert isinstance(cmd, ast.Execute) and isinstance(cmd.run, ast.Say)
    assert cmd.run.loc.line == 3 and cmd.run.loc.col == 7
    assert cmd.subcommands[1].loc.line == 2 and cmd.subcommands[1].loc.col == 5
    assert fn.commands[1].loc.line == 4


def test_error_inside_a_continued_line_points_at_its_physical_line():
    fn, diags = parse("scoreboard players \\\n  add @s x -1\n")
    assert (diags[0].line, diags[0].col) == (2, 12) and diags[0].source_line == "  add @s x -1"


def test_continuation_on_the_last_line_is_an_error():
    _, diags = parse("say a \\")
    assert "end of the file" in diags[0].message


def test_comment_lines_continue_too():
    fn, diags = parse("# comment \\\nsay swallowed\nsay kept\n")
    assert not diags and [c.message for c in fn.commands] == ["kept"]


def test_before_1_20_2_backslash_is_literal():
    fn, diags = parse("say a \\\nsay b\n", (1, 20, 1))
    assert not diags and [c.message for c in fn.commands] == ["a \\", "b"]


def test_macro_lines():
    fn, diags = parse("$scoreboard players set @s $(obj) $(value)\n$say $(obj)\n")
    assert not diags and fn.is_macro
    first = fn.commands[0]
    assert isinstance(first, ast.MacroLine)
    assert first.template == "scoreboard players set @s $(obj) $(value)" and first.keys == ("obj", "value")


def test_macro_line_errors():
    _, diags = parse("$say no variables\n$say $(bad-key)\n$say $(open\n")
    assert [d.line for d in diags] == [1, 2, 3]
    assert "without any" in diags[0].message
    assert "invalid macro variable name 'bad-key'" in diags[1].message and diags[1].col == 8
    assert "unterminated" in diags[2].message


def test_macro_lines_need_1_20_2():
    fn, diags = parse("$say $(x)\n", (1, 20, 1))
    assert not fn.commands and "1.20.2" in diags[0].message


def test_leading_slash():
    _, diags = parse("/say hi\n// comment\n")
    assert "leading '/'" in diags[0].message and "'say'" in diags[0].message
    assert "'#'" in diags[1].message


def test_crlf_and_trailing_whitespace():
    fn, diags = parse("say a  \r\nkill @s\r\n")
    assert not diags and fn.commands[0].message == "a" and isinstance(fn.commands[1], ast.Kill)


def test_overlong_command_is_an_error():
    fn, diags = parse("say " + "x" * 2_000_000 + "\nsay ok\n")
    assert "too long" in diags[0].message and [c.message for c in fn.commands] == ["ok"]


def test_lone_carriage_returns_end_lines():
    # BufferedReader.lines() ends a line at '\n', '\r' or '\r\n'
    fn, diags = parse("say a\rsay b\r\nsay c\n")
    assert not diags and [(c.message, c.loc.line) for c in fn.commands] == [("a", 1), ("b", 2), ("c", 3)]


def test_byte_order_mark_is_reported():
    fn, diags = parse("\ufeffsay a\nsay b\n")
    assert [(d.line, d.col) for d in diags] == [(1, 1)] and "byte order mark" in diags[0].message
    assert [c.message for c in fn.commands] == ["a", "b"]


def test_parsing_leaves_the_garbage_collector_as_it_was():
    # parse_function pauses the cyclic collector while it builds the AST (see parse.py)
    import gc

    from mcfunction_parser.parse import parse_function
    assert gc.isenabled()
    parse_function("say a\nbad command\n", "f", "t:f")
    assert gc.isenabled()
    gc.disable()
    try:
        parse_function("say a\n", "f", "t:f")
        assert not gc.isenabled()
    finally:
        gc.enable()
