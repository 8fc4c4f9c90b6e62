; foon2pddl, encoding instances, level 3: 17 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 18 (banana 1, bowl 1, cutting board 3, fruit salad 1, heavy cream 1, honey 1, juicer 1, knife 1, lime 1, lime juice 1, mixing bowl 1, spoon 1, strawberry 1, sugar 1, whipped cream 1, whisk 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 07-guacamole.foon:52, pick-and-place at 09-fruit_salad.foon:3, pick-and-place at 09-fruit_salad.foon:34, and no unit puts one back
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-5645504d)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    banana_in_bowl_sliced - object-state
    banana_on_cutting_board_peeled - object-state
    banana_on_cutting_board_sliced - object-state
    banana_peeled - object-state
    banana_whole - object-state
    bowl_contains_banana_honey_lime_juice_strawberry - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_fruit_salad - object-state
    bowl_contains_fruit_salad_whipped_cream - object-state
    bowl_contains_strawberry - object-state
    bowl_empty - object-state
    cutting_board_contains_banana - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_strawberry - object-state
    cutting_board_empty - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d - object-state
    heavy_cream_in_carton - object-state
    heavy_cream_in_mixing_bowl - object-state
    honey_in_bowl - object-state
    honey_in_jar - object-state
    juicer_contains_lime_juice - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_squeezed - object-state
    lime_whole - object-state
    lime_juice_in_bowl - object-state
    lime_juice_in_juicer - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_whipped_cream - object-state
    mixing_bowl_empty - object-state
    spoon_plain - object-state
    strawberry_in_bowl_sliced - object-state
    strawberry_on_cutting_board_sliced - object-state
    strawberry_on_cutting_board_whole - object-state
    strawberry_whole - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whipped_cream_in_mixing_bowl_whipped - object-state
    whipped_cream_on_fruit_salad_whipped - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_banana ?x - physical-object)  ; ?x is of type banana
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_cutting_board ?x - physical-object)  ; ?x is of type cutting_board
    (type_fruit_salad ?x - physical-object)  ; ?x is of type fruit_salad
    (type_heavy_cream ?x - physical-object)  ; ?x is of type heavy_cream
    (type_honey ?x - physical-object)  ; ?x is of type honey
    (type_juicer ?x - physical-object)  ; ?x is of type juicer
    (type_knife ?x - physical-object)  ; ?x is of type knife
    (type_lime ?x - physical-object)  ; ?x is of type lime
    (type_lime_juice ?x - physical-object)  ; ?x is of type lime_juice
    (type_mixing_bowl ?x - physical-object)  ; ?x is of type mixing_bowl
    (type_spoon ?x - physical-object)  ; ?x is of type spoon
    (type_strawberry ?x - physical-object)  ; ?x is of type strawberry
    (type_sugar ?x - physical-object)  ; ?x is of type sugar
    (type_whipped_cream ?x - physical-object)  ; ?x is of type whipped_cream
    (type_whisk ?x - physical-object)  ; ?x is of type whisk
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?heavy_cream - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_heavy_cream ?heavy_cream)
      (together ?mixing_bowl ?heavy_cream)
      (is ?mixing_bowl mixing_bowl_empty)
      (lane ?mixing_bowl mixing_bowl_empty mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream heavy_cream_in_carton)
      (lane ?heavy_cream heavy_cream_in_carton heavy_cream_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream heavy_cream_in_mixing_bowl)
      (occupied heavy_cream_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?heavy_cream heavy_cream_in_carton))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?sugar - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_sugar ?sugar)
      (together ?mixing_bowl ?sugar)
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (lane ?mixing_bowl mixing_bowl_contains_heavy_cream mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_granulated)
      (lane ?sugar sugar_granulated sugar_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
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

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?strawberry - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_strawberry ?strawberry)
      (together ?cutting_board ?strawberry)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_strawberry)
      (is ?strawberry strawberry_whole)
      (lane ?strawberry strawberry_whole strawberry_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_strawberry)
      (occupied cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?strawberry strawberry_whole))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters (?strawberry - physical-object)
    :precondition (and
      (type_strawberry ?strawberry)
      (occupied cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (lane ?strawberry strawberry_on_cutting_board_whole strawberry_on_cutting_board_sliced)
      (occupied knife_plain)
    )
    :effect (and
      (is ?strawberry strawberry_on_cutting_board_sliced)
      (not (is ?strawberry strawberry_on_cutting_board_whole))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters (?banana - physical-object)
    :precondition (and
      (type_banana ?banana)
      (is ?banana banana_whole)
      (lane ?banana banana_whole banana_peeled)
    )
    :effect (and
      (is ?banana banana_peeled)
      (not (is ?banana banana_whole))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters (?cutting_board - physical-object ?banana - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_banana ?banana)
      (together ?cutting_board ?banana)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_banana)
      (is ?banana banana_peeled)
      (lane ?banana banana_peeled banana_on_cutting_board_peeled)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_banana)
      (occupied cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?banana banana_peeled))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters (?banana - physical-object)
    :precondition (and
      (type_banana ?banana)
      (occupied cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (lane ?banana banana_on_cutting_board_peeled banana_on_cutting_board_sliced)
      (occupied knife_plain)
    )
    :effect (and
      (is ?banana banana_on_cutting_board_sliced)
      (not (is ?banana banana_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters (?bowl - physical-object ?strawberry - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_strawberry ?strawberry)
      (together ?bowl ?strawberry)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_sliced)
      (lane ?strawberry strawberry_on_cutting_board_sliced strawberry_in_bowl_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_strawberry)
      (is ?strawberry strawberry_in_bowl_sliced)
      (occupied strawberry_in_bowl_sliced)
      (not (is ?bowl bowl_empty))
      (not (is ?strawberry strawberry_on_cutting_board_sliced))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters (?bowl - physical-object ?banana - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_banana ?banana)
      (together ?bowl ?banana)
      (is ?bowl bowl_contains_strawberry)
      (lane ?bowl bowl_contains_strawberry bowl_contains_banana_strawberry)
      (is ?banana banana_on_cutting_board_sliced)
      (lane ?banana banana_on_cutting_board_sliced banana_in_bowl_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_strawberry)
      (is ?banana banana_in_bowl_sliced)
      (occupied banana_in_bowl_sliced)
      (not (is ?bowl bowl_contains_strawberry))
      (not (is ?banana banana_on_cutting_board_sliced))
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
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (is ?bowl bowl_contains_banana_strawberry))
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters (?bowl - physical-object ?honey - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_honey ?honey)
      (together ?bowl ?honey)
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (lane ?bowl bowl_contains_banana_lime_juice_strawberry bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?honey honey_in_jar)
      (lane ?honey honey_in_jar honey_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?honey honey_in_bowl)
      (occupied honey_in_bowl)
      (not (is ?bowl bowl_contains_banana_lime_juice_strawberry))
      (not (is ?honey honey_in_jar))
    )
  )

  (:action mix_u98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters (?bowl - physical-object ?fruit_salad - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_fruit_salad ?fruit_salad)
      (together ?bowl ?fruit_salad)
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (lane ?bowl bowl_contains_banana_honey_lime_juice_strawberry bowl_contains_fruit_salad)
      (occupied strawberry_in_bowl_sliced)
      (occupied banana_in_bowl_sliced)
      (occupied lime_juice_in_bowl)
      (occupied honey_in_bowl)
      (occupied spoon_plain)
      (is ?fruit_salad not-yet-made)
      (lane ?fruit_salad not-yet-made fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_fruit_salad)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (not (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry))
      (not (is ?fruit_salad not-yet-made))
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters (?mixing_bowl - physical-object ?whipped_cream - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_whipped_cream ?whipped_cream)
      (together ?mixing_bowl ?whipped_cream)
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (lane ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar mixing_bowl_contains_whipped_cream)
      (occupied heavy_cream_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (occupied whisk_plain)
      (is ?whipped_cream not-yet-made)
      (lane ?whipped_cream not-yet-made whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?whipped_cream not-yet-made))
    )
  )

  (:action scoop_u100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters (?bowl - physical-object ?fruit_salad - physical-object ?whipped_cream - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_fruit_salad ?fruit_salad)
      (type_whipped_cream ?whipped_cream)
      (together ?bowl ?fruit_salad)
      (together ?fruit_salad ?whipped_cream)
      (is ?bowl bowl_contains_fruit_salad)
      (lane ?bowl bowl_contains_fruit_salad bowl_contains_fruit_salad_whipped_cream)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (lane ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (lane ?whipped_cream whipped_cream_in_mixing_bowl_whipped whipped_cream_on_fruit_salad_whipped)
      (occupied spoon_plain)
    )
    :effect (and
      (is ?bowl bowl_contains_fruit_salad_whipped_cream)
      (occupied bowl_contains_fruit_salad_whipped_cream)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (is ?whipped_cream whipped_cream_on_fruit_salad_whipped)
      (occupied whipped_cream_on_fruit_salad_whipped)
      (not (is ?bowl bowl_contains_fruit_salad))
      (not (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl))
      (not (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl], topped {whipped cream})
    :parameters ()
    :precondition (and
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
    )
    :effect (and
      (goal-reached)
    )
  )
)
