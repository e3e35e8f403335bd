"""The project around a model: configuration, the workspace's libraries and models, suppressions, the linter."""
