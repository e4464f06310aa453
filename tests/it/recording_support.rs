//! Test support for ROS 2 recordings, written independently of nrgdb's
//! reader: `nav_msgs/msg/OccupancyGrid` serialised by hand from the ROS 2
//! message definition and the CDR rules (little-endian XCDR1, 4-byte
//! encapsulation header, each primitive aligned to its size from the
//! payload start), MCAP files written with the `mcap` crate's writer, and
//! SQLite bags in rosbag2's schema (`topics`, `messages`). Also used by
//! `benches/recording.rs`.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::io::BufWriter;
use std::path::Path;

use nrgdb::grid::{Cell, OccupancyGrid};

/// The ROS 2 message definition MCAP files carry as the schema.
pub const GRID_SCHEMA: &str = "std_msgs/Header header\nMapMetaData info\nint8[] data\n";

/// One message to write: topic, ROS 2 type, log time (ns), bytes.
pub struct Msg {
    pub topic: &'static str,
    pub kind: &'static str,
    pub time_ns: u64,
    pub data: Vec<u8>,
}

struct Cdr(Vec<u8>);

impl Cdr {
    fn align(&mut self, n: usize) {
        while !(self.0.len() - 4).is_multiple_of(n) {
            self.0.push(0);
        }
    }
    fn u32(&mut self, v: u32) {
        self.align(4);
        self.0.extend(v.to_le_bytes());
    }
    fn f32(&mut self, v: f32) {
        self.align(4);
        self.0.extend(v.to_le_bytes());
    }
    fn f64(&mut self, v: f64) {
        self.align(8);
        self.0.extend(v.to_le_bytes());
    }
}

/// `grid` as an OccupancyGrid message stamped `stamp_ns`: occupancy 0
/// (free), 100 (occupied), −1 (unknown), rows from the bottom as ROS has
/// them; `noise` shifts free cells to 1..=20 and occupied ones to 70..=99
/// (still inside the map saver's thresholds) by their position.
pub fn grid_message(grid: &OccupancyGrid, stamp_ns: u64, noise: bool) -> Vec<u8> {
    let mut c = Cdr(vec![0x00, 0x01, 0x00, 0x00]);
    c.u32((stamp_ns / 1_000_000_000) as u32);
    c.u32((stamp_ns % 1_000_000_000) as u32);
    let frame = b"map\0";
    c.u32(frame.len() as u32);
    c.0.extend(frame);
    c.u32(0);
    c.u32(0);
    c.f32(grid.resolution as f32);
    c.u32(grid.width);
    c.u32(grid.height);
    let [x, y, yaw] = grid.origin;
    for v in [x, y, 0.0, 0.0, 0.0, (yaw / 2.0).sin(), (yaw / 2.0).cos()] {
        c.f64(v);
    }
    c.u32(grid.width * grid.height);
    for row in (0..grid.height).rev() {
        for col in 0..grid.width {
            let i = (row * grid.width + col) as usize;
            let k = (i % 20) as i8;
            let v: i8 = match grid.cells[i] {
                Cell::Free if noise => 1 + k,
                Cell::Free => 0,
                Cell::Occupied if noise => 70 + k,
                Cell::Occupied => 100,
                Cell::Unknown => -1,
            };
            c.0.push(v as u8);
        }
    }
    c.0
}

/// Writes `messages` to an MCAP file as rosbag2 does (ros2msg schemas,
/// cdr messages), chunked and zstd-compressed when `compress`.
pub fn write_mcap(path: &Path, messages: &[Msg], compress: bool) {
    let file = BufWriter::new(std::fs::File::create(path).unwrap());
    let options = mcap::WriteOptions::new()
        .profile("ros2")
        .compression(compress.then_some(mcap::Compression::Zstd));
    let mut w = options.create(file).unwrap();
    let mut channels: BTreeMap<&str, u16> = BTreeMap::new();
    for (seq, m) in messages.iter().enumerate() {
        let channel = match channels.get(m.topic) {
            Some(c) => *c,
            None => {
                let schema = w
                    .add_schema(m.kind, "ros2msg", GRID_SCHEMA.as_bytes())
                    .unwrap();
                let c = w
                    .add_channel(schema, m.topic, "cdr", &BTreeMap::new())
                    .unwrap();
                channels.insert(m.topic, c);
                c
            }
        };
        let header = mcap::records::MessageHeader {
            channel_id: channel,
            sequence: seq as u32,
            log_time: m.time_ns,
            publish_time: m.time_ns,
        };
        w.write_to_known_channel(&header, &m.data).unwrap();
    }
    w.finish().unwrap();
}

/// Writes `messages` as a rosbag2 SQLite bag `dir/bag_0.db3` with its
/// `metadata.yaml`.
pub fn write_db3_bag(dir: &Path, messages: &[Msg]) {
    std::fs::create_dir_all(dir).unwrap();
    let db = rusqlite::Connection::open(dir.join("bag_0.db3")).unwrap();
    db.execute_batch(
        "CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
         CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
             serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL,
             type_description_hash TEXT NOT NULL);
         CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,
             timestamp INTEGER NOT NULL, data BLOB NOT NULL);
         INSERT INTO schema VALUES (4, 'humble');",
    )
    .unwrap();
    let mut topics: BTreeMap<&str, i64> = BTreeMap::new();
    for m in messages {
        let id = match topics.get(m.topic) {
            Some(id) => *id,
            None => {
                db.execute(
                    "INSERT INTO topics (name, type, serialization_format, offered_qos_profiles, type_description_hash) VALUES (?1, ?2, 'cdr', '', '')",
                    [m.topic, m.kind],
                )
                .unwrap();
                let id = db.last_insert_rowid();
                topics.insert(m.topic, id);
                id
            }
        };
        db.execute(
            "INSERT INTO messages (topic_id, timestamp, data) VALUES (?1, ?2, ?3)",
            rusqlite::params![id, m.time_ns as i64, m.data],
        )
        .unwrap();
    }
    let topic_list: String = topics
        .keys()
        .map(|t| {
            format!(
                "    - topic_metadata:\n        name: {t}\n        type: nav_msgs/msg/OccupancyGrid\n        serialization_format: cdr\n        offered_qos_profiles: ''\n      message_count: 1\n"
            )
        })
        .collect();
    let yaml = format!(
        "rosbag2_bagfile_information:\n  version: 8\n  storage_identifier: sqlite3\n  duration:\n    nanoseconds: 0\n  starting_time:\n    nanoseconds_since_epoch: 0\n  message_count: {}\n  topics_with_message_count:\n{topic_list}  compression_format: ''\n  compression_mode: ''\n  relative_file_paths:\n    - bag_0.db3\n  files:\n    - path: bag_0.db3\n      starting_time:\n        nanoseconds_since_epoch: 0\n      duration:\n        nanoseconds: 0\n      message_count: {}\n",
        messages.len(),
        messages.len()
    );
    std::fs::write(dir.join("metadata.yaml"), yaml).unwrap();
}
