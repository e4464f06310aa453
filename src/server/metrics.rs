//! Request metrics in the Prometheus text format (written by hand):
//! requests by route, method and status, a latency histogram per route,
//! revision cache hits and misses. The counters only: the middleware that
//! feeds them is in `track.rs`, so this file knows nothing of the
//! request state that owns them.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;
use std::sync::Mutex;
use std::time::Instant;

use super::cache::RevisionCache;

/// Upper bounds of the latency buckets, in seconds.
pub const BUCKETS_S: [f64; 12] = [
    0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 5.0,
];

#[derive(Debug, Default)]
struct RouteStats {
    by_status: BTreeMap<(String, u16), u64>,
    buckets: [u64; BUCKETS_S.len()],
    count: u64,
    sum_s: f64,
}

/// Counters of served requests.
#[derive(Debug)]
pub struct Metrics {
    routes: Mutex<HashMap<String, RouteStats>>,
    started: Instant,
}

impl Default for Metrics {
    fn default() -> Metrics {
        Metrics {
            routes: Mutex::new(HashMap::new()),
            started: Instant::now(),
        }
    }
}

impl Metrics {
    /// Counts one request on `route` (the route pattern, not the raw path).
    pub fn record(&self, route: &str, method: &str, status: u16, seconds: f64) {
        let mut routes = self.routes.lock().unwrap_or_else(|p| p.into_inner());
        let stats = match routes.get_mut(route) {
            Some(s) => s,
            None => routes.entry(route.to_string()).or_default(),
        };
        match stats.by_status.get_mut(&(method.to_string(), status)) {
            Some(n) => *n += 1,
            None => {
                stats.by_status.insert((method.to_string(), status), 1);
            }
        }
        if let Some(i) = BUCKETS_S.iter().position(|b| seconds <= *b) {
            stats.buckets[i] += 1;
        }
        stats.count += 1;
        stats.sum_s += seconds;
    }

    /// The metrics as Prometheus text (exposition format 0.0.4).
    pub fn render(&self, cache: &RevisionCache) -> String {
        let mut out = String::new();
        let routes = self.routes.lock().unwrap_or_else(|p| p.into_inner());
        let mut names: Vec<&String> = routes.keys().collect();
        names.sort();
        let _ = writeln!(
            out,
            "# HELP nrgdb_http_requests_total HTTP requests served."
        );
        let _ = writeln!(out, "# TYPE nrgdb_http_requests_total counter");
        for name in &names {
            for ((method, status), n) in &routes[*name].by_status {
                let _ = writeln!(
                    out,
                    "nrgdb_http_requests_total{{route=\"{}\",method=\"{method}\",status=\"{status}\"}} {n}",
                    escape(name)
                );
            }
        }
        let _ = writeln!(
            out,
            "# HELP nrgdb_http_request_duration_seconds Time to answer a request."
        );
        let _ = writeln!(out, "# TYPE nrgdb_http_request_duration_seconds histogram");
        for name in &names {
            let s = &routes[*name];
            let label = escape(name);
            let mut cumulative = 0;
            for (bound, n) in BUCKETS_S.iter().zip(s.buckets) {
                cumulative += n;
                let _ = writeln!(
                    out,
                    "nrgdb_http_request_duration_seconds_bucket{{route=\"{label}\",le=\"{bound}\"}} {cumulative}"
                );
            }
            let _ = writeln!(
                out,
                "nrgdb_http_request_duration_seconds_bucket{{route=\"{label}\",le=\"+Inf\"}} {}",
                s.count
            );
            let _ = writeln!(
                out,
                "nrgdb_http_request_duration_seconds_sum{{route=\"{label}\"}} {}",
                s.sum_s
            );
            let _ = writeln!(
                out,
                "nrgdb_http_request_duration_seconds_count{{route=\"{label}\"}} {}",
                s.count
            );
        }
        let (hits, misses) = cache.stats();
        let gauges = [
            (
                "nrgdb_cache_hits_total",
                "counter",
                "Revision cache hits.",
                hits as f64,
            ),
            (
                "nrgdb_cache_misses_total",
                "counter",
                "Revision cache misses (revision loaded and indexed).",
                misses as f64,
            ),
            (
                "nrgdb_cache_revisions",
                "gauge",
                "Revisions held in the cache.",
                cache.len() as f64,
            ),
            (
                "nrgdb_uptime_seconds",
                "gauge",
                "Seconds since the server started.",
                self.started.elapsed().as_secs_f64(),
            ),
        ];
        for (name, kind, help, value) in gauges {
            let _ = writeln!(
                out,
                "# HELP {name} {help}\n# TYPE {name} {kind}\n{name} {value}"
            );
        }
        out
    }
}

fn escape(label: &str) -> String {
    label.replace('\\', "\\\\").replace('"', "\\\"")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_format() {
        let m = Metrics::default();
        m.record("/maps", "GET", 200, 0.0007);
        m.record("/maps", "GET", 200, 0.2);
        m.record("/maps", "GET", 404, 0.0001);
        let text = m.render(&RevisionCache::new(1));
        assert!(text.contains(
            "nrgdb_http_requests_total{route=\"/maps\",method=\"GET\",status=\"200\"} 2"
        ));
        assert!(text.contains("le=\"0.0005\"} 1\n"));
        assert!(text.contains("le=\"0.001\"} 2\n"));
        assert!(text.contains("le=\"+Inf\"} 3\n"));
        assert!(text.contains("nrgdb_cache_misses_total 0\n"));
    }
}
