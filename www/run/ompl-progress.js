// RRT*'s best cost against time in the OMPL benchmark log, as OMPL writes an anytime planner's
// progress (ompl::tools::Benchmark::saveResultsToStream) and Planner Arena reads it
// (ompl_benchmark_statistics.py's readBenchmarkLog, into its progress table): after a planner's
// run lines and before its closing ".",
//   "2 progress properties for each run" / "time REAL" / "best cost REAL" / "<n> runs"
// then one line per run, in the runs' order: each sample "time,cost," followed by ";" (time in
// seconds, as the log's run times). The core writes the log (report/ompl.rs); the page adds the
// progress it collected from the workers. A set-up without progress keeps its block as written.

/**
 * `log` (the core's OMPL log of `report`) with each set-up's progress: `progress[k]` a Map from
 * seed to that run's [[ms, cost], ...] (none: no block for set-up k).
 * @param {string} log @param {{setups: {rows: {seed: number}[]}[]}} report @param {Map<number, number[][]>[]} progress
 * @returns {string}
 */
export function withProgress(log, report, progress) {
  const lines = log.split('\n');
  const out = [];
  let k = 0;
  for (const line of lines) {
    if (line === '.' && k < report.setups.length) {
      const runs = progress[k];
      if (runs && runs.size) {
        const rows = report.setups[k].rows;
        out.push('2 progress properties for each run', 'time REAL', 'best cost REAL', `${rows.length} runs`);
        for (const r of rows) out.push((runs.get(r.seed) ?? []).map(([ms, c]) => `${ms / 1000},${c},;`).join(''));
      }
      k++;
    }
    out.push(line);
  }
  return out.join('\n');
}
