"""gen_array.py N OUT.json: a graph whose one node, 'pick', passes a constant array of N numbers
(0, 0.001, ..., 0.999, 0, ...) to pickOne(__global const float *values, int i) and is the color
of material m (graph-array-memory.test; generated so that no large file is committed)."""
import sys


def main():
    n, out = int(sys.argv[1]), sys.argv[2]
    with open(out, "w", encoding="utf-8") as f:
        f.write('{ "texcc": 1, "nodes": [ { "id": "pick", "fn": "pickOne", "args": { "i": 1, '
                '"values": [')
        chunk = ",".join("%g" % (i / 1000.0) for i in range(1000))
        full, rest = divmod(n, 1000)
        f.write(",".join([chunk] * full))
        if rest:
            f.write(("," if full else "") + ",".join("%g" % (i / 1000.0) for i in range(rest)))
        f.write('] } } ], "materials": { "m": { "bsdf": "diffuse", "color": { "node": "pick" } '
                '} } }\n')


if __name__ == "__main__":
    main()
