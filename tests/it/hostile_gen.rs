//! Inputs for the fuzz harness (`hostile_inputs`): a valid seed per parser,
//! made here, and the mutations that turn it hostile.

use nrgdb::diff::{ChangeSet, DiffParams, apply, diff};
use nrgdb::indoorgml::{from_nrg, write_string};
use nrgdb::ingest::{IngestOptions, InputFile, read};
use nrgdb::model::Nrg;
use nrgdb::query::{Format, MemorySource, Session, demo};
use nrgdb::server::multipart;

use super::support::building;

/// The parsers a stranger can reach.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parser {
    Query,
    IndoorGml,
    Map,
    Multipart,
    ChangeSet,
}

const ALL: [Parser; 5] = [
    Parser::Query,
    Parser::IndoorGml,
    Parser::Map,
    Parser::Multipart,
    Parser::ChangeSet,
];

impl Parser {
    pub fn name(self) -> &'static str {
        match self {
            Parser::Query => "query",
            Parser::IndoorGml => "indoorgml",
            Parser::Map => "map",
            Parser::Multipart => "multipart",
            Parser::ChangeSet => "change-set",
        }
    }

    pub fn from_name(name: &str) -> Option<Parser> {
        ALL.into_iter().find(|p| p.name() == name)
    }

    /// Tokens of the format that mutations insert (`which`: the seed's
    /// part, see [`Target::seed`]).
    pub fn dictionary(self, which: usize) -> &'static [&'static str] {
        match (self, which) {
            (Parser::Query, _) => &[
                "(",
                ")",
                "NOT ",
                "EXPLAIN ",
                " OR ",
                " AND ",
                "\"",
                ";",
                "'",
                "ROUTE FROM 1 TO 2 ",
                "ALTERNATIVES 10 ",
                "WITHIN 1e308 ",
                "VIA 3 ",
                "AVOID door 4 ",
                "WITH CLEARANCE ",
                "MIN_DOOR_WIDTH ",
                "LOCATE (1e308, -1e308)",
                "DIFF demo@1 demo@1",
                "LIKE '%_%_%'",
                "NAME 3 AS ",
                "MERGE 1, 2, 3 ",
                "SPLIT 3 ALONG (1e308, -1e308) TO ",
                "WITH DOOR (NaN, 0) WIDTH ",
                "ADD DOOR BETWEEN 3 AND ",
                "REMOVE DOOR ",
                "SET 3 ATTRIBUTE ",
                "UNSET 3 ATTRIBUTE ",
                "USE nosuch;",
                "@4294967295",
                "FIND rooms WHERE ",
                "NEIGHBOURS OF ",
                "REACHABLE FROM 1 WITHIN ",
                " ORDER BY width DESC",
                " LIMIT 18446744073709551615",
                "-0",
                "NaN",
            ],
            (Parser::IndoorGml, _) => &[
                "<",
                ">",
                "</",
                "/>",
                "<gml:pos>",
                "</gml:pos>",
                "1e308 ",
                "NaN ",
                "-inf ",
                "<!DOCTYPE a [<!ENTITY e \"xxxxxxxx\">]>",
                "&e;",
                "&#0;",
                "<![CDATA[",
                "]]>",
                "xlink:href=\"#",
                "gml:id=\"",
                "<core:State>",
                "<core:CellSpace gml:id=\"c\">",
                "<gml:posList>",
                "xmlns:x=\"",
                "<core:spaceLayer>",
            ],
            (Parser::Map, 0) => &[
                "resolution: 1e-10\n",
                "resolution: 1e308\n",
                "origin: [1e308, -1e308, NaN]\n",
                "[",
                "]",
                "{",
                "}",
                "&a ",
                "*a ",
                "- ",
                ": ",
                "\n",
                "image: ../../x.pgm\n",
                "image: floor.pgm\n",
                "negate: 1\n",
                "free_thresh: 2\n",
                "occupied_thresh: -1\n",
                "!!binary ",
                "? ",
                "'",
                "\"",
            ],
            (Parser::Map, _) => &[
                "P5\n",
                "P2\n",
                "65535\n",
                "99999 99999\n",
                "0 0\n",
                "\n",
                " ",
            ],
            (Parser::Multipart, 0) => &[
                "--XyZ",
                "\r\n",
                "\r\n\r\n",
                "--XyZ--",
                "Content-Disposition: form-data; name=\"",
                "filename=\"",
                "\"",
                ";",
                "Content-Type: image/png\r\n",
            ],
            (Parser::Multipart, _) => {
                &["multipart/form-data", "; boundary=", "\"", ";", "=", "XyZ"]
            }
            (Parser::ChangeSet, _) => &[
                "[",
                "]",
                "{",
                "}",
                "\"",
                ",",
                ":",
                "1e308",
                "-1",
                "null",
                "4294967295",
                "\"added\":",
                "\"removed\":",
                "\"polygon\":",
                "[[0,0],[1e308,0],[0,1e308]]",
                "\"format\":",
            ],
        }
    }

    /// The parser's state and seeds.
    pub fn target(self) -> Target {
        match self {
            Parser::Query => {
                let mut source = MemorySource::new();
                source.insert_with_note("demo", demo::building(3), "fuzz");
                source.insert_with_note("demo", demo::building(4), "fuzz, revision 2");
                Target::Query {
                    session: Box::new(Session::with_default_map(source).expect("a session")),
                    seeds: QUERIES.iter().map(|q| q.as_bytes().to_vec()).collect(),
                }
            }
            Parser::IndoorGml => {
                Target::IndoorGml(write_string(&from_nrg(&building(3))).into_bytes())
            }
            Parser::Map => {
                let (yaml, pgm) = floor();
                Target::Map { yaml, pgm }
            }
            Parser::Multipart => {
                let (yaml, pgm) = floor();
                let mut body = Vec::new();
                for (name, file, bytes) in [
                    ("map", Some("floor.yaml"), &yaml[..]),
                    ("image", Some("floor.pgm"), &pgm[..]),
                    ("message", None, &b"re-mapped the east wing"[..]),
                ] {
                    body.extend_from_slice(b"--XyZ\r\nContent-Disposition: form-data; name=\"");
                    body.extend_from_slice(name.as_bytes());
                    if let Some(f) = file {
                        body.extend_from_slice(format!("\"; filename=\"{f}").as_bytes());
                    }
                    body.extend_from_slice(b"\"\r\n\r\n");
                    body.extend_from_slice(bytes);
                    body.extend_from_slice(b"\r\n");
                }
                body.extend_from_slice(b"--XyZ--\r\n");
                Target::Multipart {
                    body,
                    content_type: b"multipart/form-data; boundary=XyZ".to_vec(),
                }
            }
            Parser::ChangeSet => {
                let (a, b) = (building(3), building(5));
                let json = diff(&a, &b, &DiffParams::default()).to_json().into_bytes();
                Target::ChangeSet { base: a, json }
            }
        }
    }
}

/// Valid statements the query inputs start from.
const QUERIES: [&str; 15] = [
    "FIND rooms WHERE area > 10 ORDER BY area DESC LIMIT 3;",
    "ROUTE FROM \"Kitchen\" TO 5 VIA 3 AVOID door 4 WITH CLEARANCE 0.3;",
    "ROUTE FROM (2.0, 9.0) TO (10.0, 3.0) ALTERNATIVES 3;",
    "NEIGHBOURS OF \"Kitchen\";",
    "REACHABLE FROM 1 WITHIN 20;",
    "LOCATE (3.2, 7.5);",
    "DIFF demo@1 demo@2;",
    "EXPLAIN FIND doors WHERE width >= 0.8 AND NOT (kind = 'door' OR area < 1);",
    "NAME 3 AS \"Lab\";",
    "FIND spaces WHERE name LIKE 'K%' ;",
    "MERGE 3, 4 AS \"Lobby\";",
    "SPLIT 2 ALONG (0, 1) TO (30, 1) WITH DOOR (5, 1) WIDTH 0.9;",
    "ADD DOOR BETWEEN 3 AND 4 AT (4, 4) WIDTH 1;",
    "SET 3 ATTRIBUTE restricted = TRUE; UNSET 3 ATTRIBUTE restricted;",
    "REMOVE DOOR 5; SET 3 KIND corridor; ROUTE FROM 1 TO 2 AVOID WHERE attr.restricted = TRUE;",
];

/// A parser with its seeds, run over one input at a time.
pub enum Target {
    Query {
        session: Box<Session<MemorySource>>,
        seeds: Vec<Vec<u8>>,
    },
    IndoorGml(Vec<u8>),
    Map {
        yaml: Vec<u8>,
        pgm: Vec<u8>,
    },
    Multipart {
        body: Vec<u8>,
        content_type: Vec<u8>,
    },
    ChangeSet {
        base: Nrg,
        json: Vec<u8>,
    },
}

impl Target {
    /// A seed to mutate and which part of the input it is.
    pub fn seed(&self, rng: &mut Rng) -> (usize, &[u8]) {
        let coin = rng.below(2);
        match self {
            Target::Query { seeds, .. } => (0, &seeds[rng.below(seeds.len())]),
            Target::IndoorGml(gml) => (0, gml),
            Target::Map { yaml, pgm } => (coin, if coin == 0 { yaml } else { pgm }),
            Target::Multipart { body, content_type } => {
                (coin, if coin == 0 { body } else { content_type })
            }
            Target::ChangeSet { json, .. } => (0, json),
        }
    }

    /// Runs the parser (and what follows it in the product) on `input` as
    /// part `which`; whether it was accepted. Errors are fine; panics,
    /// aborts and hangs are what the harness catches.
    pub fn run(&mut self, which: usize, input: &[u8]) -> bool {
        let options = IngestOptions::default();
        match self {
            Target::Query { session, .. } => session
                .run(&String::from_utf8_lossy(input), Format::Table)
                .is_ok(),
            Target::IndoorGml(_) => read(&[InputFile::named("fuzz.gml", input)], &options).is_ok(),
            Target::Map { yaml, pgm } => {
                let (y, p) = if which == 0 {
                    (input, &pgm[..])
                } else {
                    (&yaml[..], input)
                };
                read(
                    &[
                        InputFile::named("floor.yaml", y),
                        InputFile::named("floor.pgm", p),
                    ],
                    &options,
                )
                .is_ok()
            }
            Target::Multipart { body, content_type } => {
                let (b, c) = if which == 0 {
                    (input, content_type.clone())
                } else {
                    (&body[..], input.to_vec())
                };
                multipart::boundary(&String::from_utf8_lossy(&c))
                    .is_some_and(|boundary| multipart::parse(b, &boundary).is_ok())
            }
            Target::ChangeSet { base, .. } => ChangeSet::from_json(&String::from_utf8_lossy(input))
                .is_ok_and(|cs| apply(base, &cs).is_ok()),
        }
    }
}

/// A 6 m × 4 m floor at 5 cm per pixel as a map YAML and a binary PGM: a
/// corridor along the bottom and two rooms above it, each with a doorway.
fn floor() -> (Vec<u8>, Vec<u8>) {
    let (w, h, res) = (120u32, 80u32, 0.05);
    let free = [
        (0.2, 0.2, 5.8, 1.4),
        (0.2, 1.6, 2.9, 3.8),
        (3.1, 1.6, 5.8, 3.8),
        (1.0, 1.3, 1.9, 1.7),
        (4.0, 1.3, 4.9, 1.7),
    ];
    let mut pgm = format!("P5\n{w} {h}\n255\n").into_bytes();
    for row in 0..h {
        for col in 0..w {
            let x = (f64::from(col) + 0.5) * res;
            let y = 4.0 - (f64::from(row) + 0.5) * res;
            let inside = free
                .iter()
                .any(|&(x0, y0, x1, y1)| x >= x0 && x < x1 && y >= y0 && y < y1);
            pgm.push(if inside { 254 } else { 0 });
        }
    }
    let yaml = b"image: floor.pgm\nresolution: 0.05\norigin: [-2.5, 1.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n".to_vec();
    (yaml, pgm)
}

/// SplitMix64: small, fast, fixed-seed.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }
}

/// Numbers that break naive arithmetic.
const EXTREMES: [&str; 9] = [
    "1e308",
    "-1e308",
    "1e-320",
    "NaN",
    "inf",
    "-0",
    "18446744073709551616",
    "4294967296",
    "99999999999999999999999999",
];

/// Bytes that end or open something in one of the formats.
const SPECIAL_BYTES: &[u8] = b"\0\xff\n\"<[(&;{";

/// One to four mutations of `seed`.
pub fn mutate(seed: &[u8], dictionary: &[&str], rng: &mut Rng) -> Vec<u8> {
    let mut s = seed.to_vec();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(s.len() + 1);
        match rng.below(8) {
            0 if !s.is_empty() => {
                let i = rng.below(s.len());
                s[i] = match rng.below(3) {
                    0 => rng.next() as u8,
                    1 => SPECIAL_BYTES[rng.below(SPECIAL_BYTES.len())],
                    _ => s[i] ^ (1 << rng.below(8)),
                };
            }
            1 => {
                let end = (at + 1 + rng.below(64)).min(s.len());
                s.drain(at.min(end)..end);
            }
            2 => {
                let end = (at + 1 + rng.below(64)).min(s.len());
                let piece = s[at.min(end)..end].to_vec();
                for _ in 0..1 + rng.below(3) {
                    s.splice(at..at, piece.iter().copied());
                }
            }
            3 | 4 => {
                let token = dictionary[rng.below(dictionary.len())];
                s.splice(at..at, token.bytes());
            }
            5 => {
                // A bomb: one token repeated 100 to 100 000 times.
                let token = dictionary[rng.below(dictionary.len())];
                let times = [100, 1_000, 10_000, 100_000][rng.below(4)];
                let bomb = token.repeat(times);
                s.splice(at..at, bomb.bytes());
            }
            6 => {
                // A number made extreme.
                if let Some(start) = (at..s.len()).find(|&i| s[i].is_ascii_digit()) {
                    let end = (start..s.len())
                        .find(|&i| !(s[i].is_ascii_digit() || s[i] == b'.'))
                        .unwrap_or(s.len());
                    let extreme = EXTREMES[rng.below(EXTREMES.len())];
                    s.splice(start..end, extreme.bytes());
                }
            }
            _ => s.truncate(at),
        }
    }
    s
}
