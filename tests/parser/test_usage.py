"""``help``'s messages over the game's command tree (mcfunction_parser.commands.usage):
CommandDispatcher.getSmartUsage and HelpCommand, for a permission level 2 source."""
import pytest

from mcfunction_parser import gamedata
from mcfunction_parser.commands.usage import OrderUnknown, help_count, help_messages

TREE = gamedata.command_tree((1, 21, 5))


@pytest.mark.parametrize("text,messages", [
    ("me", ["/me <action>"]),                                # one required argument
    ("kill", ["/kill [<targets>]"]),                         # an executable node: its child is optional
    ("tellraw", ["/tellraw <targets> <message>"]),           # one child followed down
    ("execute as", ["/execute as <targets> -> execute"]),    # a redirect shows its target
    ("execute rotated as", ["/execute rotated as <targets> -> execute"]),
    ("seed", []),                                            # no children: nothing sent, result 0
    ("tp", []),                                              # a redirect's own children: none
    ("stop", None),                                          # level 4: "Unknown command or insufficient permissions"
    ("nosuchcommand", None),
])
def test_help_messages(text, messages):
    assert help_messages(TREE, text) == messages
    assert help_count(TREE, text) == (None if messages is None else len(messages))


def test_where_the_registration_order_shows_it_is_not_guessed():
    # the report sorts children by name; the game keeps them in registration order
    with pytest.raises(OrderUnknown):
        help_messages(TREE, "time query")
    with pytest.raises(OrderUnknown):
        help_messages(TREE, None)
    assert help_count(TREE, "time query") == 3


def test_a_tree_without_permissions_still_hides_the_operator_commands():
    old = gamedata.command_tree((1, 20, 4))
    assert help_messages(old, "ban") is None and help_messages(old, "me") == ["/me <action>"]
