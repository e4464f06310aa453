#![cfg(test)]

mod store;
mod store_building;
mod store_cli;
