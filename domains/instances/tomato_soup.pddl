; foon2pddl, encoding instances, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 15 (basil 1, bowl 1, cutting board 2, immersion blender 1, knife 1, ladle 1, olive oil 1, onion 1, pot 1, stove 1, tomato 1, tomato soup 1, vegetable broth 1, wooden spoon 1)
; objects: 2 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, and no unit puts one back
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-4d625a69)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    basil_fresh - object-state
    basil_on_tomato_soup - object-state
    bowl_contains_basil_tomato_soup - object-state
    bowl_contains_tomato_soup - object-state
    bowl_empty - object-state
    cutting_board_contains_onion - object-state
    cutting_board_contains_tomato - object-state
    cutting_board_empty - object-state
    immersion_blender_off - object-state
    immersion_blender_on - object-state
    knife_plain - object-state
    ladle_plain - object-state
    olive_oil_in_bottle - object-state
    olive_oil_in_pot - object-state
    onion_chopped_in_pot - object-state
    onion_chopped_on_cutting_board - object-state
    onion_in_pot_sauteed - object-state
    onion_on_cutting_board_peeled - object-state
    onion_on_cutting_board_whole - object-state
    onion_whole - object-state
    pot_contains_olive_oil_on_stove - object-state
    pot_contains_olive_oil_onion_on_stove - object-state
    pot_contains_olive_oil_onion_tomato_on_stove - object-state
    pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove - object-state
    pot_contains_tomato_soup_on_stove - object-state
    pot_empty - object-state
    pot_empty_on_stove - object-state
    stove_off - object-state
    stove_on - object-state
    tomato_chopped_in_pot - object-state
    tomato_chopped_on_cutting_board - object-state
    tomato_on_cutting_board_whole - object-state
    tomato_whole - object-state
    tomato_soup_chunky_in_pot - object-state
    tomato_soup_garnished_basil_in_bowl_pureed - object-state
    tomato_soup_in_bowl_pureed - object-state
    tomato_soup_in_pot_pureed - object-state
    vegetable_broth_in_carton - object-state
    vegetable_broth_in_pot - object-state
    wooden_spoon_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_basil ?x - physical-object)  ; ?x is of type basil
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_cutting_board ?x - physical-object)  ; ?x is of type cutting_board
    (type_immersion_blender ?x - physical-object)  ; ?x is of type immersion_blender
    (type_knife ?x - physical-object)  ; ?x is of type knife
    (type_ladle ?x - physical-object)  ; ?x is of type ladle
    (type_olive_oil ?x - physical-object)  ; ?x is of type olive_oil
    (type_onion ?x - physical-object)  ; ?x is of type onion
    (type_pot ?x - physical-object)  ; ?x is of type pot
    (type_stove ?x - physical-object)  ; ?x is of type stove
    (type_tomato ?x - physical-object)  ; ?x is of type tomato
    (type_tomato_soup ?x - physical-object)  ; ?x is of type tomato_soup
    (type_vegetable_broth ?x - physical-object)  ; ?x is of type vegetable_broth
    (type_wooden_spoon ?x - physical-object)  ; ?x is of type wooden_spoon
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters (?stove - physical-object)
    :precondition (and
      (type_stove ?stove)
      (is ?stove stove_off)
      (lane ?stove stove_off stove_on)
    )
    :effect (and
      (is ?stove stove_on)
      (occupied stove_on)
      (not (is ?stove stove_off))
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?onion - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_onion ?onion)
      (together ?cutting_board ?onion)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_onion)
      (is ?onion onion_whole)
      (lane ?onion onion_whole onion_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?onion onion_whole))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (lane ?onion onion_on_cutting_board_whole onion_on_cutting_board_peeled)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_on_cutting_board_peeled)
      (not (is ?onion onion_on_cutting_board_whole))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (lane ?onion onion_on_cutting_board_peeled onion_chopped_on_cutting_board)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_chopped_on_cutting_board)
      (not (is ?onion onion_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?tomato - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_tomato ?tomato)
      (together ?cutting_board ?tomato)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_tomato)
      (is ?tomato tomato_whole)
      (lane ?tomato tomato_whole tomato_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_tomato)
      (occupied cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?tomato tomato_whole))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters (?tomato - physical-object)
    :precondition (and
      (type_tomato ?tomato)
      (occupied cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (lane ?tomato tomato_on_cutting_board_whole tomato_chopped_on_cutting_board)
      (occupied knife_plain)
    )
    :effect (and
      (is ?tomato tomato_chopped_on_cutting_board)
      (not (is ?tomato tomato_on_cutting_board_whole))
    )
  )

  (:action pick-and-place_u52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters (?pot - physical-object ?stove - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_stove ?stove)
      (is ?pot pot_empty)
      (lane ?pot pot_empty pot_empty_on_stove)
      (is ?stove stove_off)
      (lane ?stove stove_off stove_off)
    )
    :effect (and
      (is ?pot pot_empty_on_stove)
      (not (is ?pot pot_empty))
    )
  )

  (:action pour_u53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters (?pot - physical-object ?olive_oil - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_olive_oil ?olive_oil)
      (together ?pot ?olive_oil)
      (is ?pot pot_empty_on_stove)
      (lane ?pot pot_empty_on_stove pot_contains_olive_oil_on_stove)
      (is ?olive_oil olive_oil_in_bottle)
      (lane ?olive_oil olive_oil_in_bottle olive_oil_in_pot)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_on_stove)
      (is ?olive_oil olive_oil_in_pot)
      (occupied olive_oil_in_pot)
      (not (is ?pot pot_empty_on_stove))
      (not (is ?olive_oil olive_oil_in_bottle))
    )
  )

  (:action pick-and-place_u54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters (?pot - physical-object ?onion - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_onion ?onion)
      (together ?pot ?onion)
      (is ?pot pot_contains_olive_oil_on_stove)
      (lane ?pot pot_contains_olive_oil_on_stove pot_contains_olive_oil_onion_on_stove)
      (is ?onion onion_chopped_on_cutting_board)
      (lane ?onion onion_chopped_on_cutting_board onion_chopped_in_pot)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_on_stove)
      (is ?onion onion_chopped_in_pot)
      (not (is ?pot pot_contains_olive_oil_on_stove))
      (not (is ?onion onion_chopped_on_cutting_board))
    )
  )

  (:action saute_u55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied stove_on)
      (occupied olive_oil_in_pot)
      (is ?onion onion_chopped_in_pot)
      (lane ?onion onion_chopped_in_pot onion_in_pot_sauteed)
      (occupied wooden_spoon_plain)
    )
    :effect (and
      (is ?onion onion_in_pot_sauteed)
      (occupied onion_in_pot_sauteed)
      (not (is ?onion onion_chopped_in_pot))
    )
  )

  (:action pick-and-place_u56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters (?pot - physical-object ?tomato - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_tomato ?tomato)
      (together ?pot ?tomato)
      (is ?pot pot_contains_olive_oil_onion_on_stove)
      (lane ?pot pot_contains_olive_oil_onion_on_stove pot_contains_olive_oil_onion_tomato_on_stove)
      (occupied onion_in_pot_sauteed)
      (is ?tomato tomato_chopped_on_cutting_board)
      (lane ?tomato tomato_chopped_on_cutting_board tomato_chopped_in_pot)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_tomato_on_stove)
      (is ?tomato tomato_chopped_in_pot)
      (occupied tomato_chopped_in_pot)
      (not (is ?pot pot_contains_olive_oil_onion_on_stove))
      (not (is ?tomato tomato_chopped_on_cutting_board))
    )
  )

  (:action pour_u57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters (?pot - physical-object ?vegetable_broth - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_vegetable_broth ?vegetable_broth)
      (together ?pot ?vegetable_broth)
      (is ?pot pot_contains_olive_oil_onion_tomato_on_stove)
      (lane ?pot pot_contains_olive_oil_onion_tomato_on_stove pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (is ?vegetable_broth vegetable_broth_in_carton)
      (lane ?vegetable_broth vegetable_broth_in_carton vegetable_broth_in_pot)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (is ?vegetable_broth vegetable_broth_in_pot)
      (occupied vegetable_broth_in_pot)
      (not (is ?pot pot_contains_olive_oil_onion_tomato_on_stove))
      (not (is ?vegetable_broth vegetable_broth_in_carton))
    )
  )

  (:action simmer_u58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters (?pot - physical-object ?tomato_soup - physical-object)
    :precondition (and
      (type_pot ?pot)
      (type_tomato_soup ?tomato_soup)
      (together ?pot ?tomato_soup)
      (occupied stove_on)
      (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (lane ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove pot_contains_tomato_soup_on_stove)
      (occupied olive_oil_in_pot)
      (occupied onion_in_pot_sauteed)
      (occupied tomato_chopped_in_pot)
      (occupied vegetable_broth_in_pot)
      (is ?tomato_soup not-yet-made)
      (lane ?tomato_soup not-yet-made tomato_soup_chunky_in_pot)
    )
    :effect (and
      (is ?pot pot_contains_tomato_soup_on_stove)
      (occupied pot_contains_tomato_soup_on_stove)
      (is ?tomato_soup tomato_soup_chunky_in_pot)
      (not (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove))
      (not (is ?tomato_soup not-yet-made))
    )
  )

  (:action turn_on_u59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters (?immersion_blender - physical-object)
    :precondition (and
      (type_immersion_blender ?immersion_blender)
      (is ?immersion_blender immersion_blender_off)
      (lane ?immersion_blender immersion_blender_off immersion_blender_on)
    )
    :effect (and
      (is ?immersion_blender immersion_blender_on)
      (occupied immersion_blender_on)
      (not (is ?immersion_blender immersion_blender_off))
    )
  )

  (:action blend_u60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters (?tomato_soup - physical-object)
    :precondition (and
      (type_tomato_soup ?tomato_soup)
      (occupied immersion_blender_on)
      (occupied pot_contains_tomato_soup_on_stove)
      (is ?tomato_soup tomato_soup_chunky_in_pot)
      (lane ?tomato_soup tomato_soup_chunky_in_pot tomato_soup_in_pot_pureed)
    )
    :effect (and
      (is ?tomato_soup tomato_soup_in_pot_pureed)
      (not (is ?tomato_soup tomato_soup_chunky_in_pot))
    )
  )

  (:action scoop_u61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters (?tomato_soup - physical-object ?bowl - physical-object)
    :precondition (and
      (type_tomato_soup ?tomato_soup)
      (type_bowl ?bowl)
      (together ?tomato_soup ?bowl)
      (occupied pot_contains_tomato_soup_on_stove)
      (is ?tomato_soup tomato_soup_in_pot_pureed)
      (lane ?tomato_soup tomato_soup_in_pot_pureed tomato_soup_in_bowl_pureed)
      (occupied ladle_plain)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_tomato_soup)
    )
    :effect (and
      (is ?tomato_soup tomato_soup_in_bowl_pureed)
      (is ?bowl bowl_contains_tomato_soup)
      (not (is ?tomato_soup tomato_soup_in_pot_pureed))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action sprinkle_u62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters (?bowl - physical-object ?tomato_soup - physical-object ?basil - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_tomato_soup ?tomato_soup)
      (type_basil ?basil)
      (together ?bowl ?tomato_soup)
      (together ?tomato_soup ?basil)
      (is ?bowl bowl_contains_tomato_soup)
      (lane ?bowl bowl_contains_tomato_soup bowl_contains_basil_tomato_soup)
      (is ?tomato_soup tomato_soup_in_bowl_pureed)
      (lane ?tomato_soup tomato_soup_in_bowl_pureed tomato_soup_garnished_basil_in_bowl_pureed)
      (is ?basil basil_fresh)
      (lane ?basil basil_fresh basil_on_tomato_soup)
    )
    :effect (and
      (is ?bowl bowl_contains_basil_tomato_soup)
      (occupied bowl_contains_basil_tomato_soup)
      (is ?tomato_soup tomato_soup_garnished_basil_in_bowl_pureed)
      (occupied tomato_soup_garnished_basil_in_bowl_pureed)
      (is ?basil basil_on_tomato_soup)
      (occupied basil_on_tomato_soup)
      (not (is ?bowl bowl_contains_tomato_soup))
      (not (is ?tomato_soup tomato_soup_in_bowl_pureed))
      (not (is ?basil basil_fresh))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: tomato soup (garnished {basil}, in [bowl], pureed)
    :parameters ()
    :precondition (and
      (occupied tomato_soup_garnished_basil_in_bowl_pureed)
    )
    :effect (and
      (goal-reached)
    )
  )
)
