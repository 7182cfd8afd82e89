"""Command-line entry points: each a `main(argv) -> int`, the only code that prints."""
