import json
import os


class PackageNotFoundError(KeyError):
    pass


def get_package_share_directory(package_name):
    packages = json.loads(os.environ.get("URDFCLI_TEST_PACKAGES", "{}"))
    if package_name not in packages:
        raise PackageNotFoundError(package_name)
    return packages[package_name]
