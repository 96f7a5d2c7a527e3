"""Rails joining their neighbours when one is placed (BaseRailBlock.onPlace -> updateDir ->
RailState.place), with the shapes a pack reads back.

``join(blocks, pos, powered)``: the rail just placed at ``pos`` takes the shape its neighbours
allow (straight, a curve for a plain rail, ascending toward a rail one block up), and each
neighbour that can still take a connection turns to meet it (RailState.connectTo). A rail is
found beside, above or below a position (RailState.getRail); a neighbour whose two connections
both lead to rails keeps its shape. ``powered`` is whether the placed rail's block has a neighbour
signal (it picks which curve wins when four ways are open). Powered, detector and activator rails
are straight (no curves).

Each change of a rail's shape is a setBlock with neighbour updates (flag 3), and a command's change
of a block updates its neighbours too (``notify``): a rail told so checks whether it may stay
(BaseRailBlock.neighborChanged -> shouldBeRemoved: a sturdy block under it, and under its high side
when it ascends).

Not modelled (raises Unmodelled): a rail that may not stay (the game pops it off and drops it: a
rail with no sturdy block under it, an ascending one whose high side is not a full block), a powered
neighbour rail turning (its power along the line), a plain rail with three rails round it updated by
a signal source (RailBlock.updateState turns it again).

Sources: decompiled 1.21 world/level/block/RailState.java (updateConnections, removeSoftConnections,
getRail, hasConnection, canConnectTo, connectTo, hasNeighborRail, place), BaseRailBlock.java
(onPlace, updateState, updateDir, isStraight, neighborChanged, shouldBeRemoved), RailBlock.updateState.
"""
from __future__ import annotations

from emulator.world import block_shapes
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled

RAILS = ("minecraft:rail", "minecraft:powered_rail", "minecraft:detector_rail", "minecraft:activator_rail")
NORTH, SOUTH, WEST, EAST = (0, 0, -1), (0, 0, 1), (-1, 0, 0), (1, 0, 0)
_UP = (0, 1, 0)
# RailState.updateConnections: the two places each shape leads to, relative to the rail
_LINKS = {
    "north_south": (NORTH, SOUTH), "east_west": (WEST, EAST),
    "ascending_east": (WEST, (1, 1, 0)), "ascending_west": ((-1, 1, 0), EAST),
    "ascending_north": ((0, 1, -1), SOUTH), "ascending_south": (NORTH, (0, 1, 1)),
    "south_east": (EAST, SOUTH), "south_west": (WEST, SOUTH), "north_west": (WEST, NORTH), "north_east": (EAST, NORTH),
}
_HIGH_SIDE = {"ascending_east": EAST, "ascending_west": WEST, "ascending_north": NORTH, "ascending_south": SOUTH}


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


class _Rail:
    """RailState: a rail's place, state and the places it connects to."""

    def __init__(self, blocks, pos) -> None:
        self.blocks, self.pos = blocks, tuple(pos)
        self.state = blocks.get(self.pos)
        self.straight = self.state.id != "minecraft:rail"
        self.connections = [_add(self.pos, d) for d in _LINKS[self.shape]]

    @property
    def shape(self) -> str:
        return dict(self.state.properties).get("shape", "north_south")

    def _is_rail(self, pos) -> bool:
        return self.blocks.get(pos).id in RAILS

    def rail_at(self, pos) -> "_Rail | None":
        """RailState.getRail: a rail at ``pos``, else one above, else one below."""
        for candidate in (pos, _add(pos, _UP), _add(pos, (0, -1, 0))):
            if self._is_rail(candidate):
                return _Rail(self.blocks, candidate)
        return None

    def has_connection(self, pos) -> bool:
        return any(c[0] == pos[0] and c[2] == pos[2] for c in self.connections)

    def remove_soft_connections(self) -> None:
        kept = []
        for pos in self.connections:
            rail = self.rail_at(pos)
            if rail is not None and rail.has_connection(self.pos):
                kept.append(rail.pos)
        self.connections = kept

    def can_connect_to(self, other: "_Rail") -> bool:
        return self.has_connection(other.pos) or len(self.connections) != 2

    def _ascending(self, shape: str | None) -> str | None:
        if shape == "north_south":
            shape = "ascending_north" if self._is_rail(_add(_add(self.pos, NORTH), _UP)) else shape
            shape = "ascending_south" if self._is_rail(_add(_add(self.pos, SOUTH), _UP)) else shape
        if shape == "east_west":
            shape = "ascending_east" if self._is_rail(_add(_add(self.pos, EAST), _UP)) else shape
            shape = "ascending_west" if self._is_rail(_add(_add(self.pos, WEST), _UP)) else shape
        return shape

    def _set(self, shape: str) -> None:
        high = _HIGH_SIDE.get(shape)
        if high is not None and not block_shapes.is_face_sturdy(self.blocks.get(_add(self.pos, high))):
            raise Unmodelled(f"a rail ascending against {self.blocks.get(_add(self.pos, high)).id} "
                             "(BaseRailBlock.shouldBeRemoved pops it off)")
        properties = dict(self.state.properties)
        properties["shape"] = shape
        self.state = BlockState(self.state.id, tuple(sorted(properties.items())))
        self.blocks.set_state(self.pos, self.state)
        notify(self.blocks, [self.pos], self.state.id)  # Level.setBlock with flag 3

    def connect_to(self, other: "_Rail") -> None:
        """RailState.connectTo."""
        if dict(self.state.properties).get("powered") == "true":
            raise Unmodelled(f"a powered {self.state.id} turning to meet a new rail (its power along the line)")
        self.connections.append(other.pos)
        n, s, w, e = (self.has_connection(_add(self.pos, d)) for d in (NORTH, SOUTH, WEST, EAST))
        shape = None
        if n or s:
            shape = "north_south"
        if w or e:
            shape = "east_west"
        if not self.straight:
            shape = _curve(n, s, w, e) or shape
        self._set(self._ascending(shape) or "north_south")

    def place(self, powered: bool) -> None:
        """RailState.place with alwaysPlace (a rail just placed)."""
        n, s, w, e = (self._neighbour_joins(_add(self.pos, d)) for d in (NORTH, SOUTH, WEST, EAST))
        current = self.shape
        shape = None
        ns, ew = n or s, w or e
        if ns and not ew:
            shape = "north_south"
        if ew and not ns:
            shape = "east_west"
        if not self.straight:
            shape = _curve(n, s, w, e) or shape
        if shape is None:
            shape = current if ns and ew else "north_south" if ns else "east_west" if ew else None
            if not self.straight:
                corners = [("south_east", s and e), ("south_west", s and w), ("north_east", n and e),
                           ("north_west", n and w)]
                for name, open_ in (corners if powered else list(reversed(corners[2:])) + list(reversed(corners[:2]))):
                    if open_:
                        shape = name
        shape = self._ascending(shape) or current
        self._set(shape)
        self.connections = [_add(self.pos, d) for d in _LINKS[shape]]
        for pos in list(self.connections):
            rail = self.rail_at(pos)
            if rail is not None:
                rail.remove_soft_connections()
                if rail.can_connect_to(self):
                    rail.connect_to(self)

    def _neighbour_joins(self, pos) -> bool:
        """RailState.hasNeighborRail."""
        rail = self.rail_at(pos)
        if rail is None:
            return False
        rail.remove_soft_connections()
        return rail.can_connect_to(self)


def _curve(n: bool, s: bool, w: bool, e: bool) -> str | None:
    """The curve two open ways make when the other two are closed (a plain rail only)."""
    shape = None
    if s and e and not n and not w:
        shape = "south_east"
    if s and w and not n and not e:
        shape = "south_west"
    if n and w and not s and not e:
        shape = "north_west"
    if n and e and not s and not w:
        shape = "north_east"
    return shape


def join(blocks, pos, powered: bool = False) -> None:
    _Rail(blocks, pos).place(powered)


# the blocks whose signal a plain rail's neighbour update reads (RailBlock.updateState: isSignalSource)
_SIGNAL_SOURCES = ("minecraft:detector_rail", "minecraft:redstone_block", "minecraft:lever",
                   "minecraft:redstone_torch", "minecraft:redstone_wall_torch", "minecraft:target")


def notify(blocks, positions, changed_id: str) -> None:
    """Level.updateNeighborsAt for each of ``positions`` (``changed_id`` the block now there): the
    rails beside them run BaseRailBlock.neighborChanged. A rail that stays keeps its shape here;
    one the game would pop off, or turn again, raises Unmodelled."""
    signal = changed_id in _SIGNAL_SOURCES or changed_id.endswith("_button")
    for pos in positions:
        for d in (NORTH, SOUTH, WEST, EAST, _UP, (0, -1, 0)):
            beside = _add(pos, d)
            if blocks.get(beside).id in RAILS:
                _stays(blocks, beside, signal)


def _stays(blocks, pos, signal: bool) -> None:
    rail = _Rail(blocks, pos)
    below = blocks.get(_add(pos, (0, -1, 0)))
    if below.id in RAILS or not block_shapes.is_face_sturdy(below):
        raise Unmodelled(f"a {rail.state.id} with {below.id} under it popping off when a neighbour changes "
                         "(BaseRailBlock.shouldBeRemoved)")
    high = _HIGH_SIDE.get(rail.shape)
    if high is not None and (blocks.get(_add(pos, high)).id in RAILS
                             or not block_shapes.is_face_sturdy(blocks.get(_add(pos, high)))):
        raise Unmodelled(f"a rail ascending against {blocks.get(_add(pos, high)).id} popping off when a neighbour "
                         "changes (BaseRailBlock.shouldBeRemoved)")
    if signal and not rail.straight and _potential_connections(rail) == 3:
        raise Unmodelled("a rail with three rails round it updated by a signal source (RailBlock.updateState "
                         "turns it again)")


def _potential_connections(rail: "_Rail") -> int:
    """RailState.countPotentialConnections: the sides with a rail level, above or below."""
    return sum(rail.rail_at(_add(rail.pos, d)) is not None for d in (NORTH, SOUTH, WEST, EAST))
