"""Target selectors (``@s @e @a @p @r @n`` with arguments) over an :class:`EntityStore`.

``select(store, selector, source, scores=None, world=None) -> list[Entity]``
- ``selector``: a :class:`mcfunction_parser.ast.Selector`; ``source``: a :class:`Source`.
- ``scores(holder, objective) -> int | None``: the score lookup for ``scores=`` (None: no score or
  no objective, which fails the entry as in the game).
- ``world``: a :class:`SelectorWorld`: membership in entity type tags (``type=#...``) and the
  predicate test (``predicate=...``); without it only the built-in vanilla tags are known.
``select_one(...)``: the single-entity form (fails "No entity was found" / "Only one entity ...").
``SelectorQuery(selector, world).run(store, source, scores)``: the same with the selector's
tests built once, for callers that run one selector many times.

Semantics (decompiled 1.21 commands/arguments/selector/EntitySelector.java, EntitySelectorParser.java,
options/EntitySelectorOptions.java):
- ``@a @p @r`` select players only; ``@e`` and ``@n`` add an "is alive" test; ``@s`` is the
  executor if it passes every test. ``@p @n`` sort nearest, ``@r`` random, limit 1.
- Levels (EntitySelector.findEntities/findPlayers, isWorldLimited): a selector with a position,
  volume or distance argument (``x y z dx dy dz distance``: EntitySelectorOptions calls
  setWorldLimited) searches only the source's level; any other searches every level, entities in
  the server's level order (``EntityStore.entities``), players in the player list's order (the order
  they joined, ``EntityStore.players``) whichever level they are in. A selector that only finds
  players (``@a @p @r``, ``type=player``, ``gamemode``, ``level``, ``advancements``: setIncludesEntities(false))
  searches players; ``@s`` is the executor wherever it is.
- Unsorted results come in creation order, limited as they are found; ``nearest``/``furthest``
  sort stably by squared distance; ``random`` is ``Collections.shuffle`` with the table's seeded
  ``java.util.Random`` (:mod:`emulator.world.java_random`, shared with the VM).
- ``x y z`` replace the origin's coordinates; ``dx dy dz`` make a box from the origin corner
  ``[min(0,d), max(0,d) + 1]`` per axis, and an entity matches when its hitbox intersects it
  (strict ``<``); without a box, ``distance=..R`` also pre-filters by the box ``[-R, R + 1]``.
- ``distance`` compares squared distances to the entity's feet (inclusive).
- ``x_rotation``/``y_rotation``: wrapped bounds, a missing min is 0 and a missing max is 359
  (wrapped to -1), so ``x_rotation=10..`` also matches pitches below 0, as in the game.
- ``advancements={id=bool,id={criterion=bool}}``: players' advancement progress.
- ``predicate=ID``: the loaded predicate with the entity as ``this`` and its position as origin;
  an unknown id matches nothing (EntitySelectorOptions).
- ``tag=`` (empty) matches entities without tags; ``name`` compares the display name; ``nbt`` is a
  partial match on the entity NBT; ``gamemode``/``level`` only ever match players; ``team`` only
  living entities (emulator.world.living.NOT_LIVING lists the others).
"""
from __future__ import annotations

from typing import Callable

from mcfunction_parser import ast
from emulator.world import java_random, mth
from emulator.world.entities import Entity, EntityStore, entity_nbt
from emulator.world.living import NOT_LIVING
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.resources import Resources
from emulator.world.nbt_ops import compare_nbt
from emulator.world.source import Source

UNLIMITED = 2**31 - 1


def _no_scores(holder: str, objective: str) -> None:
    return None


class SelectorWorld:
    """What a selector reads from the world beyond the entities: type tags and predicates."""

    def __init__(self, in_type_tag: Callable[[str, str], bool],
                 predicate: Callable[[str, Entity], bool] | None = None,
                 advancements: Callable[[str, Entity], bool] | None = None) -> None:
        self.in_type_tag = in_type_tag
        self.predicate = predicate
        self.advancements = advancements  # (the selector's raw {...} text, entity)


def _builtin_world() -> SelectorWorld:
    resources = Resources()
    return SelectorWorld(lambda tag, type_id: resources.in_tag("entity_type", tag, type_id))


# the arguments that limit a selector to the source's level (EntitySelectorOptions: setWorldLimited)
WORLD_LIMITING = frozenset(("x", "y", "z", "dx", "dy", "dz", "distance"))

# (max results, players only, alive test, order) per selector variable.
_VARIABLES = {
    "a": (UNLIMITED, True, False, "arbitrary"),
    "e": (UNLIMITED, False, True, "arbitrary"),
    "n": (1, False, True, "nearest"),
    "p": (1, True, False, "nearest"),
    "r": (1, True, False, "random"),
    "s": (1, False, False, "arbitrary"),
}


def _distance_sq(entity: Entity, origin) -> float:
    dx, dy, dz = (a - b for a, b in zip(entity.pos, origin))
    return dx * dx + dy * dy + dz * dz


def _rotation_test(bounds: ast.FloatRange, attribute: str) -> Callable[[Entity], bool]:
    lo = float(mth.wrap_degrees_f(0.0 if bounds.lo is None else bounds.lo))
    hi = float(mth.wrap_degrees_f(359.0 if bounds.hi is None else bounds.hi))

    def test(entity: Entity) -> bool:
        value = mth.wrap_degrees_d(float(getattr(entity, attribute)))
        return value >= lo or value <= hi if lo > hi else lo <= value <= hi

    return test


def _box(deltas) -> tuple[float, ...]:
    """``EntitySelectorParser.createAabb``: from the corner, +1 on each positive extent."""
    lows = tuple(d if d < 0 else 0.0 for d in deltas)
    highs = tuple((0.0 if d < 0 else d) + 1.0 for d in deltas)
    return lows + highs


def _intersects(box, other) -> bool:
    """``AABB.intersects``: strict overlap on all three axes."""
    return all(box[i] < other[i + 3] and box[i + 3] > other[i] for i in range(3))


class SelectorQuery:
    """A selector compiled once (its tests built), run against any store and source."""

    def __init__(self, selector: ast.Selector, world: SelectorWorld | None = None) -> None:
        self.limit, self.players_only, alive, self.order = _VARIABLES[selector.variable]
        self.current = selector.variable == "s"
        self.world_limited = any(arg.key in WORLD_LIMITING for arg in selector.args)
        self.tests: list[Callable[[Entity], bool]] = [lambda e: e.alive] if alive else []
        self.world = world or _builtin_world()
        self.scores: Callable[[str, str], int | None] = _no_scores
        self.coords: dict[str, float] = {}
        self.distance: ast.FloatRange | None = None
        for arg in selector.args:
            self._add(arg)

    def _add(self, arg: ast.SelectorArg) -> None:
        key, value, neg = arg.key, arg.value, arg.negated
        if key in ("x", "y", "z", "dx", "dy", "dz"):
            self.coords[key] = float(value)
        elif key == "distance":
            self.distance = value
        elif key == "limit":
            self.limit = int(value)
        elif key == "sort":
            self.order = value
        elif key == "type":
            self._add_type(value, neg)
        elif key == "tag":
            self.tests.append(lambda e, v=value, n=neg: (not e.tags if v == "" else v in e.tags) != n)
        elif key == "name":
            self.tests.append(lambda e, v=value, n=neg: (e.display_name == v) != n)
        elif key == "nbt":
            self.tests.append(lambda e, v=value, n=neg: compare_nbt(v, entity_nbt(e)) != n)
        elif key == "scores":
            self.tests.append(lambda e, v=value: all(
                (s := self.scores(e.score_holder, obj)) is not None and rng.contains(s) for obj, rng in v))
        elif key in ("x_rotation", "y_rotation"):
            self.tests.append(_rotation_test(value, "pitch" if key == "x_rotation" else "yaw"))
        elif key == "gamemode":
            self.players_only = True
            self.tests.append(lambda e, v=value, n=neg: e.is_player and (e.gamemode == v) != n)
        elif key == "level":
            self.players_only = True
            self.tests.append(lambda e, v=value: e.is_player and v.contains(e.level))
        elif key == "team":
            self.tests.append(lambda e, v=value, n=neg: e.type not in NOT_LIVING and ((e.team or "") == v) != n)
        elif key == "predicate" and self.world.predicate is not None:
            test = self.world.predicate
            self.tests.append(lambda e, v=value, n=neg: test(v, e) != n)
        elif key == "advancements" and self.world.advancements is not None:
            self.players_only = self.players_only or value.strip("{} \t") != ""
            done = self.world.advancements
            self.tests.append(lambda e, v=value: done(v, e))
        else:
            raise Unmodelled(f"selector argument '{key}'")

    def _add_type(self, value: str, negated: bool) -> None:
        if value.startswith("#"):
            in_tag = self.world.in_type_tag
            self.tests.append(lambda e: in_tag(value[1:], e.type) != negated)
            return
        if value == "minecraft:player" and not negated:
            self.players_only = True
        self.tests.append(lambda e: (e.type == value) != negated)

    def run(self, store: EntityStore, source: Source,
            scores: Callable[[str, str], int | None] | None = None) -> list[Entity]:
        self.scores = scores or _no_scores
        origin = tuple(self.coords.get(axis, base) for axis, base in zip("xyz", source.pos))
        tests = list(self.tests)
        box = None
        if any(k in self.coords for k in ("dx", "dy", "dz")):
            box = _box(tuple(self.coords.get(k, 0.0) for k in ("dx", "dy", "dz")))
        elif self.distance is not None and self.distance.hi is not None:
            r = self.distance.hi
            box = (-r, -r, -r, r + 1.0, r + 1.0, r + 1.0)
        if box is not None:
            absolute = tuple(b + origin[i % 3] for i, b in enumerate(box))
            tests.append(lambda e: _intersects(absolute, e.bounding_box))
        if self.distance is not None:
            lo, hi = self.distance.lo, self.distance.hi
            tests.append(lambda e: (lo is None or lo * lo <= _distance_sq(e, origin))
                         and (hi is None or _distance_sq(e, origin) <= hi * hi))
        if self.players_only:
            tests.append(lambda e: e.is_player)
        if self.current:
            e = source.entity
            return [e] if e is not None and all(t(e) for t in tests) else []
        found = []
        for entity in self._candidates(store, source):
            if all(t(entity) for t in tests):
                found.append(entity)
                if self.order == "arbitrary" and len(found) >= self.limit:
                    break
        return self._sorted(found, origin, store)[: self.limit]

    def _candidates(self, store: EntityStore, source: Source) -> list[Entity]:
        """The entities searched, in the order the game visits them: the source's level's, or every level's."""
        if not self.world_limited:
            return store.players() if self.players_only else store.entities
        start, end = store.table.level_span(store.table.levels.ids[source.dimension])  # a level's are contiguous
        level = store.entities[start:end]
        return [e for e in level if e.is_player] if self.players_only else level

    def _sorted(self, found: list[Entity], origin, store: EntityStore) -> list[Entity]:
        if len(found) <= 1 or self.order == "arbitrary":
            return found
        if self.order == "random":
            java_random.shuffle(store.table.random, found, 0, len(found))
            return found
        sign = 1.0 if self.order == "nearest" else -1.0  # both sorts are stable, like List.sort
        return sorted(found, key=lambda e: sign * _distance_sq(e, origin))


def select(store: EntityStore, selector: ast.Selector, source: Source,
           scores: Callable[[str, str], int | None] | None = None,
           world: SelectorWorld | None = None) -> list[Entity]:
    return SelectorQuery(selector, world).run(store, source, scores)


def select_one(store: EntityStore, selector: ast.Selector, source: Source, **options) -> Entity:
    """``EntitySelector.findSingleEntity``."""
    found = select(store, selector, source, **options)
    if not found:
        raise CommandFailure("argument.entity.notfound.entity")
    if len(found) > 1:
        raise CommandFailure("argument.entity.toomany")
    return found[0]
