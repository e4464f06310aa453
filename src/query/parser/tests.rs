//! Parser tests: round trips, refusals and messages.

use super::*;

/// Issue 21, defect 1: nested brackets, NOTs and EXPLAINs and long OR
/// chains crashed the server by overflowing a worker's stack. Now
/// each is a syntax error naming the limit, at any size.
#[test]
fn deeply_nested_query_is_refused_not_a_crash() {
    let brackets = |n: usize| {
        format!(
            "FIND rooms WHERE {}area > 1{}",
            "(".repeat(n),
            ")".repeat(n)
        )
    };
    assert!(parse(&brackets(MAX_NESTING)).is_ok());
    for text in [
        brackets(MAX_NESTING + 1),
        brackets(20_000),
        format!("FIND rooms WHERE {}area > 1", "NOT ".repeat(5_000)),
        format!("{}FIND rooms", "EXPLAIN ".repeat(100_000)),
    ] {
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains("nest at most 64 deep"), "{e}");
    }
    let terms = |n: usize| {
        let ors = vec!["area > 1"; n].join(" OR ");
        format!("FIND rooms WHERE {ors}; FIND rooms WHERE {ors}")
    };
    assert!(parse(&terms(MAX_TERMS)).is_ok());
    let e = parse(&terms(50_000)).unwrap_err().to_string();
    assert!(e.contains("at most 256 comparisons"), "{e}");
}

/// Issue 21 paper cuts: `ALTERNATIVES 0` answered "no route" and
/// `NAME 3 AS ""` was accepted; both are errors at the value.
#[test]
fn empty_names_and_zero_alternatives_are_refused() {
    let e = parse("ROUTE FROM 1 TO 2 ALTERNATIVES 0")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("ALTERNATIVES takes 1 to 10 routes, not 0"),
        "{e}"
    );
    assert!(parse("ROUTE FROM 1 TO 2 ALTERNATIVES 3").is_ok());
    let e = parse("NAME 3 AS \"  \"").unwrap_err().to_string();
    assert!(e.contains("name cannot be empty"), "{e}");
}

/// Issue 21, defect 7: a megabyte of statements is refused at once;
/// empty statements (`;;;`) cost nothing and are not counted.
#[test]
fn too_many_statements_are_refused() {
    assert_eq!(parse(&";".repeat(1_000_000)).unwrap().len(), 0);
    assert_eq!(
        parse(&"SHOW MAPS;".repeat(MAX_STATEMENTS)).unwrap().len(),
        MAX_STATEMENTS
    );
    let e = parse(&"SHOW MAPS;".repeat(100_000))
        .unwrap_err()
        .to_string();
    assert!(e.contains("at most 1000 statements"), "{e}");
}

#[test]
fn typo_gets_a_suggestion_and_a_span() {
    let e = parse("FIND rooms;\n  ROUET FROM 1 TO 2").unwrap_err();
    let s = e.to_string();
    assert!(s.contains("found 'ROUET' (did you mean ROUTE?)"), "{s}");
    let span = e.span().unwrap();
    assert_eq!(
        (span.line, span.column, span.offset, span.len),
        (2, 3, 14, 5)
    );
}

#[test]
fn statements_round_trip() {
    let text = "ROUTE FROM room 3 TO \"Lounge\" VIA (1.5, 2.0), 7 AVOID door 4 ALTERNATIVES 2;\
        ROUTE FROM 1 TO 2 AVOID WHERE attr.restricted = TRUE; ROUTE FROM 1 TO 2 AVOID 5 WHERE kind = door;\
        NEIGHBORS OF space 1 DEPTH 2; FIND doors WHERE NOT (width < 1 OR attr.\"a b\" = NULL) \
        AND name LIKE 'K%' ORDER BY area DESC, id LIMIT 3; LOCATE (1, -2); \
        REACHABLE FROM 1 WITHIN 10; SHOW MAPS; SHOW REVISIONS OF \"willow-full\"; \
        USE demo AT REVISION 2; NAME 3 AS \"Big \\\"Room\\\"\"; DIFF 1 2; EXPLAIN FIND spaces; \
        MERGE 3, \"Hall\", (1, 2) AS \"Lobby\"; SPLIT 4 ALONG (0, 1.5) TO (9, 1.5) WITH DOOR (3, 1.5) WIDTH 0.9; \
        SPLIT corridor 2 ALONG (0, 0) TO (1, 1); ADD DOOR BETWEEN 3 AND \"Hall\" AT (4, 4) WIDTH 1.2; \
        ADD DOOR BETWEEN 3 AND 5 AT (4, 4); REMOVE DOOR door 31; SET 3 KIND corridor; \
        SET \"Hall\" ATTRIBUTE restricted = TRUE; SET 3 ATTRIBUTE \"opening hours\" = \"8-18\"; \
        SET 3 ATTRIBUTE capacity = 12; UNSET 3 ATTRIBUTE restricted; \
        ROUTE FROM (1.5, 2) ON LEVEL 0 TO (3, 4) ON LEVEL \"M\" WITH NO STAIRS";
    let parsed = parse(text).unwrap();
    assert_eq!(parsed.len(), 25);
    for s in &parsed {
        assert_eq!(&parse_statement(&s.to_string()).unwrap(), s, "{s}");
    }
}

#[test]
fn errors_name_what_was_expected() {
    let e = parse("ROUTE FROM kitchen TO 2").unwrap_err().to_string();
    assert!(e.contains("names need quotes"), "{e}");
    let e = parse("FIND rooms WHERE aera > 3").unwrap_err().to_string();
    assert!(e.contains("did you mean area?"), "{e}");
    let e = parse("FIND rooms LIMIT").unwrap_err().to_string();
    assert!(e.contains("found end of input"), "{e}");
}
