"""Retrieval with assets on demand: attribute matches, synthesis, proxies, a similarity floor."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from asset_pipeline.library_writer import write_library
from asset_pipeline.procedural import generate_asset
from asset_pipeline.procedural.attributes import COLOURS, Attributes
from holomj.jobs.synthesis import LibrarySynthesiser
from holomj.library.store import AssetLibrary
from holomj.retrieval.assets import SIMILARITY_FLOOR, AssetRetriever
from tests.asset_pipeline.look_helpers import shows


@pytest.fixture
def small_library(tmp_path: Path) -> AssetLibrary:
    bundles = [
        generate_asset("sofa", "sofa_grey", None, 0, Attributes(colour="grey")),
        generate_asset("sofa", "sofa_plain", None, 1),
        generate_asset("desk", "desk_plain", None, 0),
        generate_asset("mug", "mug_plain", None, 0),
    ]
    return AssetLibrary.open(write_library(tmp_path / "lib", "small", bundles))


def _choose(retriever, description, category, size=None, placement="floor", quantity=1):
    return retriever.choose(
        description,
        quantity=quantity,
        variance="same",
        rng=np.random.default_rng(0),
        size=size,
        placement=placement,
        category=category,
    )


def test_library_match_synthesis_and_proxy(small_library, encoder) -> None:
    retriever = AssetRetriever(
        small_library, encoder=encoder, synthesiser=LibrarySynthesiser(small_library)
    )
    (grey,) = _choose(retriever, "a grey sofa", "sofa")
    assert grey.asset_id == "sofa_grey" and grey.how == "library match"
    assert grey.attributes_honoured == {"colour": "grey"} and not grey.proxy

    pink = _choose(retriever, "a pink velvet sofa", "sofa", size=(2.0, 0.9, 0.85), quantity=2)
    assert pink[0] == pink[1] and pink[0].how == "synthesised"
    assert pink[0].attributes_asked == {"colour": "pink", "material": "velvet"}
    assert pink[0].attributes_honoured == pink[0].attributes_asked
    meta = small_library.get(pink[0].asset_id).meta
    assert meta.category == "sofa" and meta.size == (0.9, 2.0, 0.85)
    assert any(shows(v, COLOURS["pink"]) for v in meta.visual)

    # no library asset of the category, a generator exists: synthesised, not a desk
    (bed,) = _choose(retriever, "a double bed", "bed", size=(1.6, 2.1, 1.0))
    assert bed.category == "bed" and bed.how == "synthesised"

    # neither an asset nor a generator: a proxy with the asked category
    (thing,) = _choose(retriever, "a moon rover", "moon_rover", size=(1.2, 2.0, 1.1))
    assert thing.proxy and thing.how == "proxy" and thing.category == "moon_rover"
    assert small_library.get(thing.asset_id).meta.proxy
    assert any("proxy" in n for n in retriever.notes)

    # an unasked plain sofa never gets the synthesised pink one (on-demand assets are not ranked)
    (plain,) = _choose(retriever, "a sofa", "sofa")
    assert plain.asset_id in ("sofa_grey", "sofa_plain") and plain.how == "library"


def test_similarity_floor(small_library, encoder) -> None:
    retriever = AssetRetriever(
        small_library, encoder=encoder, synthesiser=LibrarySynthesiser(small_library)
    )
    assert retriever._similar_category("couch", "floor") == "sofa"
    assert retriever._similar_category("telescope", "floor") is None
    assert retriever._similar_category("treadmill", "floor") is None
    assert 0.5 < SIMILARITY_FLOOR < 1.0


def test_without_a_synthesiser_choose_ranks_as_before(small_library, encoder) -> None:
    retriever = AssetRetriever(small_library, encoder=encoder)
    (pick,) = _choose(retriever, "a pink sofa", "sofa")
    assert pick.asset_id in ("sofa_grey", "sofa_plain") and pick.attributes_asked is None


def test_part_attributes_are_synthesised_and_reported(small_library, encoder) -> None:
    retriever = AssetRetriever(
        small_library, encoder=encoder, synthesiser=LibrarySynthesiser(small_library)
    )
    # the library's desk records no drawer colour: one is made with black drawers
    (desk,) = _choose(retriever, "a desk with black drawers", "desk", size=(1.4, 0.7, 0.75))
    assert desk.how == "synthesised" and desk.category == "desk"
    assert desk.attributes_asked == {"drawers.colour": "black"}
    assert desk.attributes_honoured == {"drawers.colour": "black"}
    assert desk.attributes_how is not None
    assert desk.attributes_how["drawers"].startswith("black on the drawers")
    meta = small_library.get(desk.asset_id).meta
    drawers = [v for v in meta.visual if "__drawers_" in v.mesh]
    assert drawers and all(shows(v, COLOURS["black"]) for v in drawers)

    # asked again, the synthesised desk is found again by its id (a reuse, not a rebuild)
    (again,) = _choose(retriever, "a desk with black drawers", "desk", size=(1.4, 0.7, 0.75))
    assert again.asset_id == desk.asset_id and again.attributes_how == desk.attributes_how

    # a part the generator never makes is said to be missing
    (sofa,) = _choose(retriever, "a grey sofa with brass handles", "sofa")
    assert sofa.how == "synthesised" and sofa.attributes_honoured == {"colour": "grey"}
    assert sofa.attributes_how == {"handles": "not honoured: this sofa has no handles"}
