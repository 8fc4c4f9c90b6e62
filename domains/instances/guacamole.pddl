; foon2pddl, encoding instances, level 3: 22 of 101 units after relevance pruning
; goal: guacamole (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 18 (avocado 1, bowl 1, cilantro 1, cutting board 5, fork 1, guacamole 1, juicer 1, knife 1, lime 1, lime juice 1, onion 1, salt 1, spoon 1, tomato 1)
; objects: 5 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 07-guacamole.foon:3, pick-and-place at 07-guacamole.foon:52, ... (1 more), and no unit puts one back
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-4079d6e7)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    avocado_halved_on_cutting_board - object-state
    avocado_in_bowl_mashed - object-state
    avocado_in_bowl_scooped - object-state
    avocado_on_cutting_board_whole - object-state
    avocado_whole - object-state
    bowl_contains_avocado - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_tomato - object-state
    bowl_contains_avocado_lime_juice - object-state
    bowl_contains_avocado_lime_juice_onion - object-state
    bowl_contains_avocado_lime_juice_onion_tomato - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_cucumber - object-state
    bowl_contains_cucumber_tomato - object-state
    bowl_contains_guacamole - object-state
    bowl_empty - object-state
    cilantro_chopped_in_bowl - object-state
    cilantro_chopped_on_cutting_board - object-state
    cilantro_fresh - object-state
    cilantro_fresh_on_cutting_board - object-state
    cutting_board_contains_avocado - object-state
    cutting_board_contains_cilantro - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_onion - object-state
    cutting_board_contains_tomato - object-state
    cutting_board_empty - object-state
    fork_plain - object-state
    guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl - object-state
    juicer_contains_lime_juice - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_squeezed - object-state
    lime_whole - object-state
    lime_juice_in_bowl - object-state
    lime_juice_in_juicer - object-state
    onion_chopped_in_bowl - object-state
    onion_chopped_on_cutting_board - object-state
    onion_on_cutting_board_peeled - object-state
    onion_on_cutting_board_whole - object-state
    onion_whole - object-state
    salt_granulated - object-state
    salt_in_bowl - object-state
    spoon_plain - object-state
    tomato_chopped_in_bowl - object-state
    tomato_chopped_on_cutting_board - object-state
    tomato_on_cutting_board_whole - object-state
    tomato_whole - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_avocado ?x - physical-object)  ; ?x is of type avocado
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_cilantro ?x - physical-object)  ; ?x is of type cilantro
    (type_cutting_board ?x - physical-object)  ; ?x is of type cutting_board
    (type_fork ?x - physical-object)  ; ?x is of type fork
    (type_guacamole ?x - physical-object)  ; ?x is of type guacamole
    (type_juicer ?x - physical-object)  ; ?x is of type juicer
    (type_knife ?x - physical-object)  ; ?x is of type knife
    (type_lime ?x - physical-object)  ; ?x is of type lime
    (type_lime_juice ?x - physical-object)  ; ?x is of type lime_juice
    (type_onion ?x - physical-object)  ; ?x is of type onion
    (type_salt ?x - physical-object)  ; ?x is of type salt
    (type_spoon ?x - physical-object)  ; ?x is of type spoon
    (type_tomato ?x - physical-object)  ; ?x is of type tomato
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

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?avocado - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_avocado ?avocado)
      (together ?cutting_board ?avocado)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_avocado)
      (is ?avocado avocado_whole)
      (lane ?avocado avocado_whole avocado_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_avocado)
      (occupied cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?avocado avocado_whole))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters (?avocado - physical-object)
    :precondition (and
      (type_avocado ?avocado)
      (occupied cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (lane ?avocado avocado_on_cutting_board_whole avocado_halved_on_cutting_board)
      (occupied knife_plain)
    )
    :effect (and
      (is ?avocado avocado_halved_on_cutting_board)
      (not (is ?avocado avocado_on_cutting_board_whole))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters (?avocado - physical-object ?bowl - physical-object)
    :precondition (and
      (type_avocado ?avocado)
      (type_bowl ?bowl)
      (together ?avocado ?bowl)
      (is ?avocado avocado_halved_on_cutting_board)
      (lane ?avocado avocado_halved_on_cutting_board avocado_in_bowl_scooped)
      (occupied spoon_plain)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_avocado)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_scooped)
      (is ?bowl bowl_contains_avocado)
      (not (is ?avocado avocado_halved_on_cutting_board))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters (?avocado - physical-object)
    :precondition (and
      (type_avocado ?avocado)
      (is ?avocado avocado_in_bowl_scooped)
      (lane ?avocado avocado_in_bowl_scooped avocado_in_bowl_mashed)
      (occupied fork_plain)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_mashed)
      (occupied avocado_in_bowl_mashed)
      (not (is ?avocado avocado_in_bowl_scooped))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?lime - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_lime ?lime)
      (together ?cutting_board ?lime)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_lime)
      (is ?lime lime_whole)
      (lane ?lime lime_whole lime_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_lime)
      (occupied cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?lime lime_whole))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters (?lime - physical-object)
    :precondition (and
      (type_lime ?lime)
      (occupied cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (lane ?lime lime_on_cutting_board_whole lime_halved_on_cutting_board)
      (occupied knife_plain)
    )
    :effect (and
      (is ?lime lime_halved_on_cutting_board)
      (not (is ?lime lime_on_cutting_board_whole))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters (?lime - physical-object ?juicer - physical-object ?lime_juice - physical-object)
    :precondition (and
      (type_lime ?lime)
      (type_juicer ?juicer)
      (type_lime_juice ?lime_juice)
      (together ?lime ?juicer)
      (together ?juicer ?lime_juice)
      (is ?lime lime_halved_on_cutting_board)
      (lane ?lime lime_halved_on_cutting_board lime_squeezed)
      (is ?juicer juicer_empty)
      (lane ?juicer juicer_empty juicer_contains_lime_juice)
      (is ?lime_juice not-yet-made)
      (lane ?lime_juice not-yet-made lime_juice_in_juicer)
    )
    :effect (and
      (is ?lime lime_squeezed)
      (occupied lime_squeezed)
      (is ?juicer juicer_contains_lime_juice)
      (occupied juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (not (is ?lime lime_halved_on_cutting_board))
      (not (is ?juicer juicer_empty))
      (not (is ?lime_juice not-yet-made))
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters (?lime_juice - physical-object ?bowl - physical-object)
    :precondition (and
      (type_lime_juice ?lime_juice)
      (type_bowl ?bowl)
      (together ?lime_juice ?bowl)
      (occupied juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (lane ?lime_juice lime_juice_in_juicer lime_juice_in_bowl)
      (is ?bowl bowl_contains_avocado)
      (lane ?bowl bowl_contains_avocado bowl_contains_avocado_lime_juice)
      (occupied avocado_in_bowl_mashed)
    )
    :effect (and
      (is ?lime_juice lime_juice_in_bowl)
      (occupied lime_juice_in_bowl)
      (is ?bowl bowl_contains_avocado_lime_juice)
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (is ?bowl bowl_contains_avocado))
    )
  )

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters (?bowl - physical-object ?onion - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_onion ?onion)
      (together ?bowl ?onion)
      (is ?bowl bowl_contains_avocado_lime_juice)
      (lane ?bowl bowl_contains_avocado_lime_juice bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_on_cutting_board)
      (lane ?onion onion_chopped_on_cutting_board onion_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_in_bowl)
      (occupied onion_chopped_in_bowl)
      (not (is ?bowl bowl_contains_avocado_lime_juice))
      (not (is ?onion onion_chopped_on_cutting_board))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - physical-object ?tomato - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_tomato ?tomato)
      (together ?bowl ?tomato)
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (lane ?bowl bowl_contains_avocado_lime_juice_onion bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_on_cutting_board)
      (lane ?tomato tomato_chopped_on_cutting_board tomato_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (occupied tomato_chopped_in_bowl)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion))
      (not (is ?tomato tomato_chopped_on_cutting_board))
    )
  )

  (:action pick-and-place_u73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters (?cutting_board - physical-object ?cilantro - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_cilantro ?cilantro)
      (together ?cutting_board ?cilantro)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_cilantro)
      (is ?cilantro cilantro_fresh)
      (lane ?cilantro cilantro_fresh cilantro_fresh_on_cutting_board)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_cilantro)
      (occupied cutting_board_contains_cilantro)
      (is ?cilantro cilantro_fresh_on_cutting_board)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?cilantro cilantro_fresh))
    )
  )

  (:action chop_u74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters (?cilantro - physical-object)
    :precondition (and
      (type_cilantro ?cilantro)
      (occupied cutting_board_contains_cilantro)
      (is ?cilantro cilantro_fresh_on_cutting_board)
      (lane ?cilantro cilantro_fresh_on_cutting_board cilantro_chopped_on_cutting_board)
      (occupied knife_plain)
    )
    :effect (and
      (is ?cilantro cilantro_chopped_on_cutting_board)
      (not (is ?cilantro cilantro_fresh_on_cutting_board))
    )
  )

  (:action pick-and-place_u75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters (?bowl - physical-object ?cilantro - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_cilantro ?cilantro)
      (together ?bowl ?cilantro)
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (lane ?bowl bowl_contains_avocado_lime_juice_onion_tomato bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is ?cilantro cilantro_chopped_on_cutting_board)
      (lane ?cilantro cilantro_chopped_on_cutting_board cilantro_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is ?cilantro cilantro_chopped_in_bowl)
      (occupied cilantro_chopped_in_bowl)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato))
      (not (is ?cilantro cilantro_chopped_on_cutting_board))
    )
  )

  (:action sprinkle_u76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters (?bowl - physical-object ?salt - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_salt ?salt)
      (together ?bowl ?salt)
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (lane ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?salt salt_granulated)
      (lane ?salt salt_granulated salt_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?salt salt_in_bowl)
      (occupied salt_in_bowl)
      (not (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato))
      (not (is ?salt salt_granulated))
    )
  )

  (:action mix_u77
    ; unit 77: mix from 07-guacamole.foon:240
    ; mix: bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), avocado (in [bowl], mashed), lime juice (in [bowl]), onion (chopped, in [bowl]), tomato (chopped, in [bowl]), cilantro (chopped, in [bowl]), salt (in [bowl]), for...
    :parameters (?bowl - physical-object ?guacamole - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_guacamole ?guacamole)
      (together ?bowl ?guacamole)
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (lane ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato bowl_contains_guacamole)
      (occupied avocado_in_bowl_mashed)
      (occupied lime_juice_in_bowl)
      (occupied onion_chopped_in_bowl)
      (occupied tomato_chopped_in_bowl)
      (occupied cilantro_chopped_in_bowl)
      (occupied salt_in_bowl)
      (occupied fork_plain)
      (is ?guacamole not-yet-made)
      (lane ?guacamole not-yet-made guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_guacamole)
      (occupied bowl_contains_guacamole)
      (is ?guacamole guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
      (occupied guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
      (not (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato))
      (not (is ?guacamole not-yet-made))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - physical-object ?tomato - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_tomato ?tomato)
      (together ?bowl ?tomato)
      (is ?bowl bowl_contains_cucumber)
      (lane ?bowl bowl_contains_cucumber bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_on_cutting_board)
      (lane ?tomato tomato_chopped_on_cutting_board tomato_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_tomato)
      (occupied bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (occupied tomato_chopped_in_bowl)
      (not (is ?bowl bowl_contains_cucumber))
      (not (is ?tomato tomato_chopped_on_cutting_board))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters (?lime_juice - physical-object ?bowl - physical-object)
    :precondition (and
      (type_lime_juice ?lime_juice)
      (type_bowl ?bowl)
      (together ?lime_juice ?bowl)
      (occupied juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (lane ?lime_juice lime_juice_in_juicer lime_juice_in_bowl)
      (is ?bowl bowl_contains_banana_strawberry)
      (lane ?bowl bowl_contains_banana_strawberry bowl_contains_banana_lime_juice_strawberry)
    )
    :effect (and
      (is ?lime_juice lime_juice_in_bowl)
      (occupied lime_juice_in_bowl)
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (occupied bowl_contains_banana_lime_juice_strawberry)
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (is ?bowl bowl_contains_banana_strawberry))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: guacamole (contains {avocado, cilantro, lime juice, onion, salt, tomato}, in [bowl])
    :parameters ()
    :precondition (and
      (occupied guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
    )
    :effect (and
      (goal-reached)
    )
  )
)
