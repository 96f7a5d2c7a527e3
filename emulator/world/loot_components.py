"""Item functions that write one component whole, in the form its codec saves (defaults left out):
a written book's cover and pages, a writable book's pages, fireworks, a firework star's explosion,
a banner's patterns, an item's attribute modifiers and its tooltip display; and ``furnace_smelt``
and ``discard``, which give another stack. Lists change by a list operation (ListOperation:
replace_all, replace_section, insert, append), which :func:`list_operation` runs for these and
``set_lore``.

Sources (decompiled 1.21): world/level/storage/loot/functions/SetBookCoverFunction.java,
SetWrittenBookPagesFunction.java, SetWritableBookPagesFunction.java, SetFireworksFunction.java,
SetFireworkExplosionFunction.java, SetBannerPatternFunction.java, SetAttributesFunction.java,
ToggleTooltips.java (1.21.5), SmeltItemFunction.java, DiscardItem.java; util/ListOperation.java;
world/item/component/WrittenBookContent.java (EMPTY, CODEC, withReplacedPages),
WritableBookContent.java, Fireworks.java, FireworkExplosion.java, ItemAttributeModifiers.java,
TooltipDisplay.java; world/level/block/entity/BannerPatternLayers.java; server/network/
Filterable.java (saved as ``{raw, filtered?}``).
"""
from __future__ import annotations

from mcfunction_parser.nbt import Byte, Compound, Double, Int, IntArray, List, String
from emulator.world import equipment, furnaces, living
from emulator.world.items import EMPTY, ItemStack, set_component
from emulator.world.loot_context import LootContext, namespaced as _id, not_modelled, number, stored_text, to_tag
from emulator.world.mth import F32

MAX_PAGES = 100  # WritableBookContent / WrittenBookContent.MAX_PAGES
MODIFIER_IDS = (1, 21, 0)  # attribute modifiers named by an id
TOOLTIP_DISPLAY = (1, 21, 5)  # the tooltip_display component (hidden components)
BARE_MODIFIER_LIST = (1, 21, 5)  # ItemAttributeModifiers saved as its list (show_in_tooltip gone to tooltip_display)
MAX_EXPLOSIONS = 256  # Fireworks.MAX_EXPLOSIONS
_SMALL_BALL = "small_ball"  # FireworkExplosion.DEFAULT's shape


def list_operation(f: dict, current: list, values: list, max_size: int) -> list:
    """ListOperation.apply, the operation read from ``f``'s ``mode`` (with ``offset`` and
    ``size``): an offset past the end, or a result over ``max_size``, leaves the list as it was (the
    game logs an error)."""
    mode = f.get("mode", "replace_all")
    if isinstance(mode, dict):
        mode = mode.get("type", "replace_all")
    mode = str(mode).split(":")[-1]
    offset = int(f.get("offset", 0))
    if mode == "replace_all":
        return list(values)
    if mode == "append":
        return current + list(values) if len(current) + len(values) <= max_size else current
    if offset > len(current):
        return current
    if mode == "insert":
        result = current[:offset] + list(values) + current[offset:]
    elif mode == "replace_section":
        result = current[:offset] + list(values) + current[offset + int(f.get("size", len(values))):]
    else:
        raise not_modelled("list operation", mode)
    return result if len(result) <= max_size else current


def _filterable(value) -> Compound:
    """Filterable.codec's saved form: ``{raw}`` (and ``filtered`` when there is one)."""
    if isinstance(value, dict) and "raw" in value:
        return Compound((key, to_tag(value[key])) for key in ("raw", "filtered") if key in value)
    return Compound(raw=to_tag(value))


def _book(stack: ItemStack, name: str) -> Compound:
    current = stack.component(name)
    return Compound(current) if isinstance(current, dict) else Compound()


def _set_book_cover(f, stack, ctx):
    """SetBookCoverFunction: ``title``, ``author`` and ``generation`` over the written book content,
    WrittenBookContent.EMPTY (title "", author "", generation 0, no pages, resolved) when there is none."""
    book = _book(stack, "minecraft:written_book_content")
    if not book:
        book = Compound(title=_filterable(""), author=String(""), resolved=Byte(1))
    if "title" in f:
        book["title"] = _filterable(f["title"])
    if "author" in f:
        book["author"] = String(f["author"])
    if "generation" in f:
        book["generation"] = Int(f["generation"])
    if "title" in book and not isinstance(book["title"], dict):
        book["title"] = _filterable(str(book["title"]))
    if int(book.get("generation", 0)) == 0:  # optionalFieldOf("generation", 0): the default is not saved
        book.pop("generation", None)
    set_component(stack, "minecraft:written_book_content", book)
    return stack


def _set_written_book_pages(f, stack, ctx):
    """SetWrittenBookPagesFunction: ``pages`` (text components, or ``{raw, filtered}``) by the list
    operation, at most 100, over the written book content (WrittenBookContent.EMPTY when none);
    withReplacedPages leaves the book not resolved. A page is stored as the release stores text."""
    book = _book(stack, "minecraft:written_book_content")
    if not book:
        book = Compound(title=_filterable(""), author=String(""))
    current = [p if isinstance(p, dict) and "raw" in p else Compound(raw=p) for p in book.get("pages", [])]
    pages = list_operation(f, current, [_page(p, ctx.version) for p in f.get("pages", [])], MAX_PAGES)
    book.pop("pages", None)
    book.pop("resolved", None)  # withReplacedPages: resolved false, the default, not saved
    if pages:
        book["pages"] = List(pages)
    set_component(stack, "minecraft:written_book_content", book)
    return stack


def _page(page, version) -> Compound:
    if isinstance(page, dict) and "raw" in page:
        return Compound((key, stored_text(page[key], version)) for key in ("raw", "filtered") if key in page)
    return Compound(raw=stored_text(page, version))


def _set_writable_book_pages(f, stack, ctx):
    """SetWritableBookPagesFunction: ``pages`` (texts, or ``{raw, filtered}``) by the list operation,
    at most 100."""
    book = _book(stack, "minecraft:writable_book_content")
    current = [p if isinstance(p, dict) else _filterable(p) for p in book.get("pages", [])]
    pages = list_operation(f, current, [_filterable(p) for p in f.get("pages", [])], MAX_PAGES)
    set_component(stack, "minecraft:writable_book_content", Compound(pages=List(pages)) if pages else Compound())
    return stack


# the flags' names: an explosion's own (FireworkExplosion.CODEC), SetFireworkExplosionFunction's
_EXPLOSION_FLAGS = {"has_trail": "has_trail", "has_twinkle": "has_twinkle"}
_FUNCTION_FLAGS = {"has_trail": "trail", "has_twinkle": "twinkle"}


def _explosion(spec: dict, base: Compound | None = None, flags: dict = _EXPLOSION_FLAGS) -> Compound:
    """A FireworkExplosion in its saved form: ``shape``, then ``colors`` and ``fade_colors`` (int
    arrays, NbtOps' list of ints) and ``has_trail``/``has_twinkle`` when not the defaults; ``spec``'s
    fields over ``base`` (its flags named as ``flags`` says)."""
    out = Compound(base or {})
    out.setdefault("shape", String(_SMALL_BALL))
    if "shape" in spec:
        out["shape"] = String(str(spec["shape"]))
    for key in ("colors", "fade_colors"):
        if key in spec:
            out[key] = IntArray(int(c) for c in spec[key])
    for key, name in flags.items():
        if name in spec:
            out[key] = Byte(bool(spec[name]))
    for key in ("colors", "fade_colors"):
        if key in out and not out[key]:
            del out[key]
    for key in ("has_trail", "has_twinkle"):
        if key in out and not out[key]:
            del out[key]
    return out


def _set_firework_explosion(f, stack, ctx):
    """SetFireworkExplosionFunction: each of ``shape``, ``colors``, ``fade_colors``, ``trail`` and
    ``twinkle`` given over the star's explosion, FireworkExplosion.DEFAULT (a small ball) when none."""
    current = stack.component("minecraft:firework_explosion")
    set_component(stack, "minecraft:firework_explosion",
                  _explosion(f, current if isinstance(current, dict) else None, _FUNCTION_FLAGS))
    return stack


def _set_fireworks(f, stack, ctx):
    """SetFireworksFunction: ``explosions`` (``{values, mode}``: a list operation, at most 256) and
    ``flight_duration`` over the fireworks, Fireworks(0, []) when there are none."""
    current = stack.component("minecraft:fireworks")
    fireworks = Compound(current) if isinstance(current, dict) else Compound()
    if "explosions" in f:
        spec = f["explosions"]
        old = list(fireworks.get("explosions", []))
        new = list_operation(spec, old, [_explosion(e) for e in spec.get("values", [])], MAX_EXPLOSIONS)
        fireworks["explosions"] = List(new)
    if "flight_duration" in f:
        fireworks["flight_duration"] = Byte(int(f["flight_duration"]))
    if not fireworks.get("explosions", True):
        del fireworks["explosions"]
    if int(fireworks.get("flight_duration", 0)) == 0:
        fireworks.pop("flight_duration", None)
    set_component(stack, "minecraft:fireworks", fireworks)
    return stack


def _layer(layer: dict) -> Compound:
    pattern = layer.get("pattern")
    if not isinstance(pattern, str):
        raise not_modelled("set_banner_pattern pattern", "an inline banner pattern")
    return Compound(pattern=String(_id(pattern)), color=String(str(layer.get("color", "white"))))


def _set_banner_pattern(f, stack, ctx):
    """SetBannerPatternFunction: the ``patterns`` after the banner's own (``append``) or instead of them."""
    layers = [_layer(layer) for layer in f.get("patterns", [])]
    current = stack.component("minecraft:banner_patterns")
    if f.get("append", False) and isinstance(current, list):
        layers = list(current) + layers
    set_component(stack, "minecraft:banner_patterns", List(layers))
    return stack


def _set_attributes(f, stack, ctx):
    """SetAttributesFunction (1.21+): each modifier added to the item's (withModifierAdded: one of
    the same attribute and id is replaced), its slot group drawn from its ``slot`` list
    (Util.getRandom) before its ``amount`` (getFloat, a float saved as a double); ``replace``
    (default true) starts from none, else from the item's modifiers (its defaults when it has none)."""
    version = tuple(ctx.version)
    if version < MODIFIER_IDS:
        raise not_modelled("set_attributes", "before 1.21 (modifiers named by a UUID and a name)")
    current = stack.component("minecraft:attribute_modifiers")
    entries = [] if f.get("replace", True) else _entries(current) or [
        _entry(m.attribute, m.id, m.amount, m.operation, m.slot, version)
        for m in equipment.default_modifiers(stack.id)]
    for modifier in f.get("modifiers", []):
        slots = modifier.get("slot", "any")
        slots = slots if isinstance(slots, list) else [slots]
        slot = slots[ctx.random.randrange(len(slots))]
        amount = float(F32(number(modifier.get("amount", 0.0), ctx)))
        attribute, modifier_id = living.attribute_id(modifier.get("attribute", "")), _id(modifier.get("id", ""))
        entries = [e for e in entries if not (living.attribute_id(str(e.get("type", ""))) == attribute
                                              and str(e.get("id", "")) == modifier_id)]
        operation = str(modifier.get("operation", "add_value"))
        entries.append(_entry(attribute, modifier_id, amount, operation, slot, version))
    if version >= BARE_MODIFIER_LIST:
        set_component(stack, "minecraft:attribute_modifiers", List(entries))
        return stack
    wrapped = Compound(modifiers=List(entries))
    if isinstance(current, dict) and "show_in_tooltip" in current and not f.get("replace", True):
        wrapped["show_in_tooltip"] = current["show_in_tooltip"]
    set_component(stack, "minecraft:attribute_modifiers", wrapped)
    return stack


def _entries(component) -> list:
    found = component.get("modifiers", []) if isinstance(component, dict) else component or []
    return [Compound(e) for e in found if isinstance(e, dict)]


def _entry(attribute: str, modifier_id: str, amount: float, operation: str, slot: str, version) -> Compound:
    """ItemAttributeModifiers.Entry as saved: ``type`` (the release's attribute id), the modifier's
    ``id``, ``amount``, ``operation``, and ``slot`` unless it is ``any``."""
    entry = Compound(type=String(living.saved_attribute_id(attribute, version)), id=String(modifier_id),
                     amount=Double(amount), operation=String(operation))
    if slot != "any":
        entry["slot"] = String(slot)
    return entry


def _furnace_smelt(f, stack, ctx):
    """SmeltItemFunction: the first smelting recipe that takes the item gives its result, with the
    stack's count; with none the stack stays (the game logs a warning). Without the game's data
    its own recipes are not known: an item no pack recipe takes is not modelled."""
    if stack.is_empty:
        return stack
    found = furnaces.recipe_for("minecraft:furnace", stack, ctx.resources, ctx.version)
    result = furnaces.recipe_result(found[1], ctx.version) if found is not None else EMPTY
    if result.is_empty:
        return stack
    result = result.copy()
    result.count = stack.count  # copyWithCount
    return result


def _toggle_tooltips(f, stack, ctx):
    """ToggleTooltips from 1.21.5: each of ``toggles`` (component -> shown) in order, over the
    item's tooltip display (TooltipDisplay.withHidden: a hidden component appended to
    ``hidden_components``, a shown one taken out). Before 1.21.5 each component kept its own
    ``show_in_tooltip``: not modelled."""
    if tuple(ctx.version) < TOOLTIP_DISPLAY:
        raise not_modelled("toggle_tooltips", "before 1.21.5 (each component's show_in_tooltip)")
    current = stack.component("minecraft:tooltip_display")
    display = Compound(current) if isinstance(current, dict) else Compound()
    hidden = [str(c) for c in display.get("hidden_components", [])]
    for name, shown in f.get("toggles", {}).items():
        name = _id(name)
        if shown and name in hidden:
            hidden.remove(name)
        elif not shown and name not in hidden:
            hidden.append(name)
    display.pop("hidden_components", None)
    if hidden:
        display["hidden_components"] = List(String(c) for c in hidden)
    if display:
        set_component(stack, "minecraft:tooltip_display", display)
    else:  # TooltipDisplay.DEFAULT: the item's own, no patch
        stack.patch.pop("minecraft:tooltip_display", None)
    return stack


def _discard(f, stack: ItemStack, ctx: LootContext) -> ItemStack:
    """DiscardItem: the stack is gone."""
    return EMPTY.copy()


FUNCTIONS = {f"minecraft:{k}": v for k, v in {
    "set_book_cover": _set_book_cover, "set_written_book_pages": _set_written_book_pages,
    "set_writable_book_pages": _set_writable_book_pages,
    "set_firework_explosion": _set_firework_explosion, "set_fireworks": _set_fireworks,
    "set_banner_pattern": _set_banner_pattern, "set_attributes": _set_attributes, "toggle_tooltips": _toggle_tooltips,
    "furnace_smelt": _furnace_smelt, "discard": _discard}.items()}
