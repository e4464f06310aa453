#![cfg(test)]

mod query;
mod query_cli;
mod query_golden;
mod query_props;
mod route_props;
