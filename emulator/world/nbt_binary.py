"""Reading binary NBT (the format of ``.nbt`` structure files) into the values of
:mod:`mcfunction_parser.nbt`.

``read_nbt(data)``: a file's bytes (gzip-compressed, as the game writes structures, or raw) ->
``(root name, Compound)``. Big-endian; strings in Java's modified UTF-8; a list keeps its element
type even when empty (as ``List`` here it is just a list). Anything malformed raises
:class:`NbtFormatError` saying what was expected at which byte offset.

Source: the NBT format as NbtIo.read / TagTypes implement it (decompiled 1.21 nbt/NbtIo.java,
nbt/*Tag.java): tag ids 0 End .. 12 LongArray; a named root tag; NbtAccounter's depth limit 512.
"""
from __future__ import annotations

import gzip
import struct
import zlib

from mcfunction_parser.nbt import (Byte, ByteArray, Compound, Double, Float, Int, IntArray, List, Long,
                                   LongArray, Short, String)

MAX_DEPTH = 512  # NbtAccounter: "Tried to read NBT tag with too high complexity, depth > 512"
_NUMBERS = {1: (Byte, ">b", 1), 2: (Short, ">h", 2), 3: (Int, ">i", 4), 4: (Long, ">q", 8),
            5: (Float, ">f", 4), 6: (Double, ">d", 8)}
_ARRAYS = {7: (ByteArray, Byte, ">b", 1), 11: (IntArray, Int, ">i", 4), 12: (LongArray, Long, ">q", 8)}
COMPOUND = 10


class NbtFormatError(ValueError):
    pass


def read_nbt(data: bytes) -> tuple[str, Compound]:
    """The root compound of an NBT file (gzip-compressed or not) and its name."""
    if data[:2] == b"\x1f\x8b":
        try:
            data = gzip.decompress(data)
        except (OSError, EOFError, zlib.error) as error:
            raise NbtFormatError(f"broken gzip data ({error})") from None
    reader = _Reader(data)
    kind = reader.unsigned(1, "the root tag's type")
    if kind != COMPOUND:
        raise NbtFormatError(f"the root tag must be a compound (type 10), found type {kind}")
    name = reader.string()
    root = reader.payload(COMPOUND, 0)
    if reader.pos != len(data):
        raise NbtFormatError(f"{len(data) - reader.pos} unexpected bytes after the root compound")
    return name, root


class _Reader:
    def __init__(self, data: bytes) -> None:
        self.data, self.pos = data, 0

    def take(self, n: int, what: str) -> bytes:
        if n < 0 or self.pos + n > len(self.data):
            raise NbtFormatError(f"the file ends at byte {len(self.data)} inside {what} (at byte {self.pos})")
        chunk = self.data[self.pos:self.pos + n]
        self.pos += n
        return chunk

    def unsigned(self, n: int, what: str) -> int:
        return int.from_bytes(self.take(n, what), "big")

    def number(self, fmt: str, size: int, what: str):
        return struct.unpack(fmt, self.take(size, what))[0]

    def string(self) -> String:
        start = self.pos
        raw = self.take(self.unsigned(2, "a string's length"), "a string")
        try:
            return String(_modified_utf8(raw))
        except UnicodeDecodeError:
            raise NbtFormatError(f"the string at byte {start} is not modified UTF-8") from None

    def payload(self, kind: int, depth: int):
        if depth > MAX_DEPTH:
            raise NbtFormatError(f"tags nested deeper than {MAX_DEPTH}")
        if kind in _NUMBERS:
            cls, fmt, size = _NUMBERS[kind]
            return cls(self.number(fmt, size, cls.__name__))
        if kind == 8:
            return self.string()
        if kind in _ARRAYS:
            cls, item, fmt, size = _ARRAYS[kind]
            count = self.number(">i", 4, f"a {cls.__name__}'s length")
            return cls(item(self.number(fmt, size, cls.__name__)) for _ in range(self._count(count, size)))
        if kind == 9:
            element = self.unsigned(1, "a list's element type")
            count = self.number(">i", 4, "a list's length")
            if count > 0 and element == 0:
                raise NbtFormatError(f"a list of {count} End tags (byte {self.pos})")
            return List(self.payload(element, depth + 1) for _ in range(self._count(count, 1)))
        if kind == COMPOUND:
            compound = Compound()
            while (child := self.unsigned(1, "a compound's next tag type")) != 0:
                key = self.string()
                compound[str(key)] = self.payload(child, depth + 1)
            return compound
        raise NbtFormatError(f"unknown tag type {kind} (byte {self.pos - 1})")

    def _count(self, count: int, size: int) -> int:
        if count < 0 or self.pos + count * size > len(self.data):
            raise NbtFormatError(f"a length of {count} at byte {self.pos - 4} runs past the end of the file")
        return count


def _modified_utf8(raw: bytes) -> str:
    """Java's DataInput.readUTF: U+0000 as C0 80, characters past U+FFFF as two surrogates."""
    text = raw.replace(b"\xc0\x80", b"\x00").decode("utf-8", "surrogatepass")
    return text.encode("utf-16", "surrogatepass").decode("utf-16")
