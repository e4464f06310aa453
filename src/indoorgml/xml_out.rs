//! A thin, indenting XML emitter over quick-xml's `Writer`, with the few
//! shapes IndoorGML needs: start/end tags, text leaves and empty elements.

use std::io::{self, Write};

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};

/// Writes indented XML.
pub struct XmlOut<W: Write> {
    writer: Writer<W>,
}

impl<W: Write> XmlOut<W> {
    /// An emitter indenting by two spaces.
    pub fn new(inner: W) -> XmlOut<W> {
        XmlOut {
            writer: Writer::new_with_indent(inner, b' ', 2),
        }
    }

    /// The `<?xml …?>` declaration.
    pub fn declaration(&mut self) -> io::Result<()> {
        self.writer
            .write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))
    }

    /// `<name attrs…>`.
    pub fn start(&mut self, name: &str, attrs: &[(&str, &str)]) -> io::Result<()> {
        let tag = BytesStart::new(name).with_attributes(attrs.iter().copied());
        self.writer.write_event(Event::Start(tag))
    }

    /// `<name gml:id="id">`, or `<name>` when the id is empty.
    pub fn start_id(&mut self, name: &str, id: &str) -> io::Result<()> {
        if id.is_empty() {
            self.start(name, &[])
        } else {
            self.start(name, &[("gml:id", id)])
        }
    }

    /// `</name>`.
    pub fn end(&mut self, name: &str) -> io::Result<()> {
        self.writer.write_event(Event::End(BytesEnd::new(name)))
    }

    /// `<name attrs…/>`.
    pub fn empty(&mut self, name: &str, attrs: &[(&str, &str)]) -> io::Result<()> {
        let tag = BytesStart::new(name).with_attributes(attrs.iter().copied());
        self.writer.write_event(Event::Empty(tag))
    }

    /// `<name attrs…>text</name>`, text escaped.
    pub fn leaf(&mut self, name: &str, attrs: &[(&str, &str)], text: &str) -> io::Result<()> {
        self.start(name, attrs)?;
        self.writer.write_event(Event::Text(BytesText::new(text)))?;
        self.end(name)
    }

    /// `<name xlink:href="#target"/>`.
    pub fn href(&mut self, name: &str, target: &str) -> io::Result<()> {
        let href = format!("#{target}");
        self.empty(name, &[("xlink:href", &href)])
    }

    /// Ends the document with a newline and returns the inner writer.
    pub fn finish(mut self) -> io::Result<W> {
        self.writer.get_mut().write_all(b"\n")?;
        Ok(self.writer.into_inner())
    }
}
