//! A small element tree built with quick-xml's namespace-aware reader:
//! every element knows its namespace, local name, attributes, direct text
//! and source line. The IndoorGML reader walks this tree.

use std::borrow::Cow;
use std::collections::HashMap;
use std::rc::Rc;

use quick_xml::NsReader;
use quick_xml::events::{BytesStart, Event};
use quick_xml::name::ResolveResult;

use super::IndoorGmlError;

/// IndoorGML 1.0 core namespace.
pub const NS_CORE: &str = "http://www.opengis.net/indoorgml/1.0/core";
/// IndoorGML 1.0 navigation namespace.
pub const NS_NAVI: &str = "http://www.opengis.net/indoorgml/1.0/navigation";
/// GML 3.2 namespace.
pub const NS_GML: &str = "http://www.opengis.net/gml/3.2";
/// XLink namespace.
pub const NS_XLINK: &str = "http://www.w3.org/1999/xlink";
/// XML Schema instance namespace.
pub const NS_XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";

/// Elements nested deeper than this are refused (IndoorGML needs ~20).
const MAX_DEPTH: usize = 256;

/// The namespace of an element or attribute.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Ns {
    /// IndoorGML core.
    Core,
    /// IndoorGML navigation.
    Navi,
    /// GML 3.2.
    Gml,
    /// XLink.
    Xlink,
    /// XML Schema instance.
    Xsi,
    /// Any other namespace URI.
    Other(Rc<str>),
    /// No namespace.
    None,
}

impl Ns {
    fn from_uri(uri: &str) -> Ns {
        match uri {
            NS_CORE => Ns::Core,
            NS_NAVI => Ns::Navi,
            NS_GML => Ns::Gml,
            NS_XLINK => Ns::Xlink,
            NS_XSI => Ns::Xsi,
            other => Ns::Other(Rc::from(other)),
        }
    }

    /// The namespace URI, or "" for none.
    pub fn uri(&self) -> &str {
        match self {
            Ns::Core => NS_CORE,
            Ns::Navi => NS_NAVI,
            Ns::Gml => NS_GML,
            Ns::Xlink => NS_XLINK,
            Ns::Xsi => NS_XSI,
            Ns::Other(u) => u,
            Ns::None => "",
        }
    }
}

/// An attribute.
#[derive(Debug, Clone)]
pub struct Attr {
    /// Its namespace.
    pub ns: Ns,
    /// Local name.
    pub name: String,
    /// Unescaped value.
    pub value: String,
}

/// An element with its children, borrowing text from the source where it
/// can.
#[derive(Debug, Clone)]
pub struct Element<'a> {
    /// Its namespace.
    pub ns: Ns,
    /// Local name (interned: elements share one allocation per name).
    pub name: Rc<str>,
    /// Attributes.
    pub attrs: Vec<Attr>,
    /// Child elements in order.
    pub children: Vec<Element<'a>>,
    /// Concatenated direct text (not trimmed; leading indentation dropped).
    pub text: Cow<'a, str>,
    /// 1-based line of the start tag.
    pub line: usize,
}

impl<'a> Element<'a> {
    /// Whether this element is `ns:name`.
    pub fn is(&self, ns: &Ns, name: &str) -> bool {
        &self.ns == ns && &*self.name == name
    }

    /// The value of attribute `ns:name`.
    pub fn attr(&self, ns: &Ns, name: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|a| &a.ns == ns && a.name == name)
            .map(|a| a.value.as_str())
    }

    /// The `gml:id`.
    pub fn gml_id(&self) -> Option<&str> {
        self.attr(&Ns::Gml, "id")
    }

    /// The `xlink:href`, without a leading `#`.
    pub fn href(&self) -> Option<&str> {
        self.attr(&Ns::Xlink, "href")
            .map(|h| h.trim().trim_start_matches('#'))
    }

    /// Child elements named `ns:name`.
    pub fn children_named<'s>(
        &'s self,
        ns: &'s Ns,
        name: &'s str,
    ) -> impl Iterator<Item = &'s Element<'a>> + 's {
        self.children.iter().filter(move |c| c.is(ns, name))
    }

    /// The first child named `ns:name`.
    pub fn child(&self, ns: &Ns, name: &str) -> Option<&Element<'a>> {
        self.children.iter().find(|c| c.is(ns, name))
    }

    /// The element's text, trimmed.
    pub fn trimmed_text(&self) -> &str {
        self.text.trim()
    }

    /// `prefix-less` qualified name for messages: `{uri}name` or `name`.
    pub fn qualified_name(&self) -> String {
        match &self.ns {
            Ns::Core => format!("core:{}", self.name),
            Ns::Navi => format!("navi:{}", self.name),
            Ns::Gml => format!("gml:{}", self.name),
            Ns::None => self.name.to_string(),
            other => format!("{{{}}}{}", other.uri(), self.name),
        }
    }
}

/// Maps byte offsets to 1-based line numbers.
struct LineIndex {
    newlines: Vec<usize>,
}

impl LineIndex {
    fn new(text: &str) -> LineIndex {
        LineIndex {
            newlines: memchr::memchr_iter(b'\n', text.as_bytes()).collect(),
        }
    }

    fn line_at(&self, pos: usize) -> usize {
        1 + self.newlines.partition_point(|&nl| nl < pos)
    }
}

/// Parses a whole document into its root element.
pub fn parse(text: &str) -> Result<Element<'_>, IndoorGmlError> {
    let mut reader = NsReader::from_str(text);
    let mut names: HashMap<String, Rc<str>> = HashMap::new();
    let lines = LineIndex::new(text);
    let mut stack: Vec<Element<'_>> = Vec::new();
    let mut root: Option<Element<'_>> = None;
    loop {
        let start_pos = reader.buffer_position() as usize;
        let event = reader.read_event();
        let event = match event {
            Ok(e) => e,
            Err(err) => {
                let line = lines.line_at(reader.error_position() as usize);
                return Err(IndoorGmlError::Xml {
                    line,
                    message: err.to_string(),
                });
            }
        };
        // The event starts after any whitespace skipped before `<`.
        let tag_pos = text
            .get(start_pos..)
            .map_or(start_pos, |rest| start_pos + rest.find('<').unwrap_or(0));
        match event {
            Event::Start(e) => {
                let line = lines.line_at(tag_pos);
                let el = element(&reader, &e, line, &mut names)?;
                if stack.len() >= MAX_DEPTH {
                    return Err(IndoorGmlError::Xml {
                        line,
                        message: format!("elements nested deeper than {MAX_DEPTH} levels"),
                    });
                }
                stack.push(el);
            }
            Event::Empty(e) => {
                let line = lines.line_at(tag_pos);
                let el = element(&reader, &e, line, &mut names)?;
                attach(&mut stack, &mut root, el, line)?;
            }
            Event::End(_) => {
                let line = lines.line_at(tag_pos);
                if let Some(el) = stack.pop() {
                    attach(&mut stack, &mut root, el, line)?;
                }
            }
            Event::Text(t) => {
                if let Some(top) = stack.last_mut() {
                    let content = t.xml10_content();
                    // Indentation between child elements is not content.
                    if top.text.is_empty() {
                        if !content.trim_ascii().is_empty() {
                            top.text = content;
                        }
                    } else {
                        top.text.to_mut().push_str(&content);
                    }
                }
            }
            Event::CData(t) => {
                if let Some(top) = stack.last_mut() {
                    top.text.to_mut().push_str(&t.xml10_content());
                }
            }
            Event::GeneralRef(r) => {
                let line = lines.line_at(tag_pos);
                let resolved = resolve_entity(&r).ok_or_else(|| IndoorGmlError::Xml {
                    line,
                    message: format!("unknown entity &{};", r.xml10_content()),
                })?;
                if let Some(top) = stack.last_mut() {
                    top.text.to_mut().push(resolved);
                }
            }
            Event::Eof => break,
            Event::Decl(_) | Event::PI(_) | Event::Comment(_) | Event::DocType(_) => {}
        }
    }
    if let Some(open) = stack.last() {
        return Err(IndoorGmlError::Xml {
            line: open.line,
            message: format!(
                "element <{}> is never closed (the file may be truncated)",
                open.name
            ),
        });
    }
    root.ok_or(IndoorGmlError::Xml {
        line: 1,
        message: "the document has no root element".into(),
    })
}

fn resolve_entity(r: &quick_xml::events::BytesRef<'_>) -> Option<char> {
    if let Ok(Some(c)) = r.resolve_char_ref() {
        return Some(c);
    }
    match r.xml10_content().as_ref() {
        "amp" => Some('&'),
        "lt" => Some('<'),
        "gt" => Some('>'),
        "quot" => Some('"'),
        "apos" => Some('\''),
        _ => None,
    }
}

fn attach<'a>(
    stack: &mut [Element<'a>],
    root: &mut Option<Element<'a>>,
    el: Element<'a>,
    line: usize,
) -> Result<(), IndoorGmlError> {
    match stack.last_mut() {
        Some(parent) => parent.children.push(el),
        None if root.is_none() => *root = Some(el),
        None => {
            return Err(IndoorGmlError::Xml {
                line,
                message: "more than one root element".into(),
            });
        }
    }
    Ok(())
}

fn element<'a>(
    reader: &NsReader<&[u8]>,
    e: &BytesStart<'_>,
    line: usize,
    names: &mut HashMap<String, Rc<str>>,
) -> Result<Element<'a>, IndoorGmlError> {
    let (ns, local) = reader.resolver().resolve_element(e.name());
    let ns = namespace(ns, line, e.name().as_ref())?;
    let local = local.into_inner();
    let name = match names.get(local) {
        Some(n) => n.clone(),
        None => {
            let n: Rc<str> = Rc::from(local);
            names.insert(local.to_string(), n.clone());
            n
        }
    };
    let mut attrs = Vec::new();
    if e.attributes_raw().trim_ascii().is_empty() {
        return Ok(Element {
            ns,
            name,
            attrs,
            children: Vec::new(),
            text: Cow::Borrowed(""),
            line,
        });
    }
    for attr in e.attributes() {
        let attr = attr.map_err(|err| IndoorGmlError::Xml {
            line,
            message: err.to_string(),
        })?;
        let key = attr.key;
        let raw = key.as_ref();
        if raw == "xmlns" || raw.starts_with("xmlns:") {
            continue;
        }
        let (ans, alocal) = reader.resolver().resolve_attribute(key);
        let ans = namespace(ans, line, raw)?;
        let value = attr
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|err| IndoorGmlError::Xml {
                line,
                message: format!("attribute {raw}: {err}"),
            })?
            .into_owned();
        attrs.push(Attr {
            ns: ans,
            name: alocal.into_inner().to_string(),
            value,
        });
    }
    Ok(Element {
        ns,
        name,
        attrs,
        children: Vec::new(),
        text: Cow::Borrowed(""),
        line,
    })
}

fn namespace(r: ResolveResult<'_>, line: usize, name: &str) -> Result<Ns, IndoorGmlError> {
    match r {
        ResolveResult::Bound(ns) => Ok(Ns::from_uri(ns.0)),
        ResolveResult::Unbound => Ok(Ns::None),
        ResolveResult::Unknown(prefix) => Err(IndoorGmlError::Xml {
            line,
            message: format!("<{name}> uses the prefix '{prefix}', which no xmlns declares"),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolves_any_prefix_and_counts_lines() {
        let xml = "<?xml version=\"1.0\"?>\n<x:IndoorFeatures xmlns:x=\"http://www.opengis.net/indoorgml/1.0/core\"\n  xmlns:g=\"http://www.opengis.net/gml/3.2\" g:id=\"a&amp;b\">\n  <g:name>R &lt;1&gt;</g:name>\n</x:IndoorFeatures>";
        let root = parse(xml).unwrap();
        assert!(root.is(&Ns::Core, "IndoorFeatures"));
        assert_eq!(root.gml_id(), Some("a&b"));
        assert_eq!(root.line, 2);
        let name = root.child(&Ns::Gml, "name").unwrap();
        assert_eq!(name.trimmed_text(), "R <1>");
        assert_eq!(name.line, 4);
    }

    #[test]
    fn truncated_and_malformed_documents_are_errors() {
        let err = parse("<a>\n<b>\n").unwrap_err().to_string();
        assert!(
            err.contains("line 2") && err.contains("never closed"),
            "{err}"
        );
        let err = parse("<a>\n</b>").unwrap_err().to_string();
        assert!(err.contains("line"), "{err}");
        let err = parse("<p:a/>").unwrap_err().to_string();
        assert!(err.contains("prefix 'p'"), "{err}");
    }

    #[test]
    fn deep_nesting_is_refused() {
        let xml = "<a>".repeat(MAX_DEPTH + 1);
        assert!(
            parse(&xml)
                .unwrap_err()
                .to_string()
                .contains("nested deeper")
        );
    }
}
