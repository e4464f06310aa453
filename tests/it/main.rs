#![cfg(test)]
mod sim;
