#![cfg(test)]
mod extract;
