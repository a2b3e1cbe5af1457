"""bench_csv.py — reading the CSV rows that ample_bench writes (docs/results/<suite>.csv)."""


def param(r, key, default=None):
    """the value of parameter `key` in a row's "parameters" column ("k=v k=v ..."), as text"""
    for kv in r["parameters"].split():
        k, v = kv.split("=")
        if k == key:
            return v
    return default
