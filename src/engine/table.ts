// Struct-of-arrays storage: one typed array per field, grown by doubling outside step() so that step() itself
// never allocates. Dense tables keep their rows packed (swap-remove), so solver loops run over [0, count).

export type Column = Float64Array | Int32Array | Uint32Array | Uint8Array;

export function grown<T extends Column>(array: T, capacity: number): T {
  if (array.length >= capacity) return array;
  const next = new (array.constructor as { new (n: number): T })(Math.max(capacity, array.length * 2, 16));
  next.set(array);
  return next;
}

/** A table whose columns are the instance fields named by `columns`. */
export abstract class Table {
  count = 0;
  abstract readonly columns: readonly string[];

  private get self(): Record<string, Column> {
    return this as unknown as Record<string, Column>;
  }

  /** Makes room for `extra` more rows. */
  reserve(extra: number): void {
    const need = this.count + extra;
    for (const name of this.columns) this.self[name] = grown(this.self[name], need);
  }

  /** Appends a zeroed row and returns its index. */
  pushRow(): number {
    this.reserve(1);
    const i = this.count++;
    for (const name of this.columns) this.self[name][i] = 0;
    return i;
  }

  /** Appends a row holding `values` (other columns zero) and returns its index. Not for hot paths. */
  pushValues(values: Partial<Record<this['columns'][number], number>>): number {
    const row = this.pushRow();
    for (const [name, value] of Object.entries(values)) this.self[name][row] = value as number;
    return row;
  }

  /** Moves the last row into row i. Returns the index the moved row came from. */
  swapRemove(i: number): number {
    const last = --this.count;
    if (i !== last) for (const name of this.columns) this.self[name][i] = this.self[name][last];
    return last;
  }

  snapshot(): Column[] {
    return this.columns.map((name) => this.self[name].slice(0, this.count));
  }

  restore(columns: Column[], count: number): void {
    this.count = 0;
    this.reserve(count);
    this.columns.forEach((name, k) => {
      const target = this.self[name];
      target.fill(0);
      target.set(columns[k]);
    });
    this.count = count;
  }
}
