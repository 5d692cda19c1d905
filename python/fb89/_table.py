"""fb89.Table: an experiment's result, the same columns and rows as the command's CSV."""

import numpy as np


def _typed(values):
    """A column's values as int64 when every one is an integer, float64 when every one is a
    number (inf and nan included), else as text."""
    for kind in (np.int64, np.float64):
        try:
            return np.array([kind(v) for v in values], dtype=kind)
        except (ValueError, OverflowError):
            continue
    return np.array(values, dtype=str)


class Table:
    """Rows of named columns, as `fb89 experiment`, `sweep` and `calibrate` write them as CSV.

    table.columns             the column names, in the CSV's order
    table.rows                the rows, as the CSV's text
    table["hs_cpu_ms"]        a column as a numpy array (int64, float64 or str)
    table.to_numpy()          a structured array, one field a column
    table.to_pandas()         a pandas DataFrame (needs pandas, which fb89 does not)
    table.csv()               the CSV text the command writes
    str(table)                the aligned text the command prints
    """

    def __init__(self, columns, rows, text="", csv=""):
        self.columns = list(columns)
        self.rows = [tuple(r) for r in rows]
        self._text = text
        self._csv = csv
        self._typed = {}

    def __len__(self):
        return len(self.rows)

    def __iter__(self):
        """Each row as a dict of column name to value (typed as its column)."""
        columns = [self[c] for c in self.columns]
        for i in range(len(self.rows)):
            yield {name: col[i].item() for name, col in zip(self.columns, columns)}

    def __getitem__(self, column):
        if column not in self.columns:
            raise KeyError(f"{column!r}: not a column (the columns are {', '.join(self.columns)})")
        if column not in self._typed:
            k = self.columns.index(column)
            self._typed[column] = _typed([r[k] for r in self.rows])
        return self._typed[column]

    def to_numpy(self):
        """The table as a numpy structured array: one field a column, typed as __getitem__."""
        columns = [self[c] for c in self.columns]
        dtype = [(name, col.dtype) for name, col in zip(self.columns, columns)]
        out = np.empty(len(self.rows), dtype=dtype)
        for name, col in zip(self.columns, columns):
            out[name] = col
        return out

    def to_pandas(self):
        """The table as a pandas DataFrame (pandas is optional: ImportError without it)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Table.to_pandas needs pandas (fb89 does not depend on it: "
                              "apt-get install python3-pandas, or use to_numpy())") from e
        return pandas.DataFrame({c: self[c] for c in self.columns}, columns=self.columns)

    def csv(self):
        """The CSV text, as the command's --csv writes it."""
        return self._csv

    def __str__(self):
        return self._text

    def __repr__(self):
        return f"<fb89.Table {len(self.rows)} rows: {', '.join(self.columns)}>"
