# SPDX-License-Identifier: BSD-3-Clause
"""RFC 6901 JSON pointers into a model, with one extension: a segment "*" stands for every element
of an array (the held velocities of a body, say). Written here rather than taken from the
jsonpointer package because the extension is needed and the rest is a dozen lines."""


def _unescape(segment):
    return segment.replace("~1", "/").replace("~0", "~")


def _child(node, segment, pointer):
    if isinstance(node, list):
        if not segment.isdigit() or int(segment) >= len(node):
            raise KeyError("%s: no element %r in an array of %d" % (pointer, segment, len(node)))
        return int(segment)
    if isinstance(node, dict):
        if segment not in node:
            raise KeyError("%s: no member %r (members: %s)" % (pointer, segment, ", ".join(node)))
        return segment
    raise KeyError("%s: %r leads into a %s, not an object or array" % (pointer, segment, type(node).__name__))


def locations(document, pointer, create=False):
    """Every (container, key) the pointer designates; KeyError naming the pointer if one is
    missing (with create, the last segment may name a new member of an existing object)."""
    segments = [_unescape(s) for s in pointer.split("/")[1:]]
    found = [(None, None, document)]
    for depth, segment in enumerate(segments):
        last = depth == len(segments) - 1
        following = []
        for _, _, node in found:
            if segment == "*":
                if not isinstance(node, list):
                    raise KeyError("%s: * needs an array, found a %s" % (pointer, type(node).__name__))
                following += [(node, k, v) for k, v in enumerate(node)]
            elif create and last and isinstance(node, dict) and segment not in node:
                following.append((node, segment, None))
            else:
                key = _child(node, segment, pointer)
                following.append((node, key, node[key]))
        found = following
    if not segments:
        raise KeyError("%s: the pointer designates the whole model" % pointer)
    return [(container, key) for container, key, _ in found]


def set_value(document, pointer, value, create=False):
    """Sets every location of the pointer. The location must exist (a misspelt path is an error
    here, not a run failing later) unless create is set: then, as JSON Patch's "add", the last
    segment may be a new member of an existing object (the model reader rejects unknown keys)."""
    for container, key in locations(document, pointer, create):
        container[key] = value


def scale_values(document, pointer, factor):
    """Multiplies the number (or each number of the array) at every location by factor."""
    for container, key in locations(document, pointer):
        value = container[key]
        if isinstance(value, list):
            if not all(isinstance(v, (int, float)) for v in value):
                raise KeyError("%s: an array of numbers expected, found %r" % (pointer, value))
            container[key] = [v * factor for v in value]
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            container[key] = value * factor
        else:
            raise KeyError("%s: a number expected, found %r" % (pointer, value))
