; foon2pddl, encoding ocp, level 3: 11 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-f984793f)
  (:requirements :strips)
  (:constants
    air
    bottle
    bowl
    carton
    cutting_board
    knife
    ladle
    olive_oil
    onion
    pot
    stove
    table
    tomato
    tomato_soup
    vegetable_broth
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-chopped ?o)  ; ?o is chopped
    (is-whole ?o)  ; ?o is whole
  )

  (:action pick-and-place_onion_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (under onion table)
      (on table onion)
    )
    :effect (and
      (on cutting_board onion)
      (under onion cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (not (on cutting_board air))
    )
  )

  (:action chop_onion_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_tomato_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (under tomato table)
      (on table tomato)
    )
    :effect (and
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (not (on cutting_board air))
    )
  )

  (:action chop_tomato_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (is-whole tomato)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped tomato)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_pot_52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters ()
    :precondition (and
      (in pot air)
      (under pot table)
      (on table pot)
      (under stove table)
      (on table stove)
    )
    :effect (and
      (on stove pot)
      (under pot stove)
      (on table pot)
      (under stove table)
      (on table stove)
      (in pot air)
    )
  )

  (:action pour_olive_oil_53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters ()
    :precondition (and
      (in pot air)
      (on stove pot)
      (under pot stove)
      (in bottle olive_oil)
      (under olive_oil bottle)
    )
    :effect (and
      (in pot olive_oil)
      (under olive_oil pot)
      (in bottle olive_oil)
      (on stove pot)
      (under pot stove)
      (not (in pot air))
    )
  )

  (:action pick-and-place_onion_54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (is-chopped onion)
      (on cutting_board onion)
      (under onion cutting_board)
    )
    :effect (and
      (in pot onion)
      (under onion pot)
      (on cutting_board onion)
      (on stove pot)
      (under pot stove)
      (is-chopped onion)
    )
  )

  (:action pick-and-place_tomato_56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in pot onion)
      (under onion pot)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in pot tomato)
      (under tomato pot)
      (under onion pot)
      (on cutting_board tomato)
      (on stove pot)
      (under pot stove)
      (is-chopped tomato)
    )
  )

  (:action pour_vegetable_broth_57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in carton vegetable_broth)
      (under vegetable_broth carton)
    )
    :effect (and
      (in pot vegetable_broth)
      (under vegetable_broth pot)
      (in carton vegetable_broth)
      (on stove pot)
      (under pot stove)
    )
  )

  (:action simmer_58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove pot)
      (under pot stove)
      (in pot olive_oil)
      (under olive_oil pot)
      (in pot onion)
      (under onion pot)
      (is-chopped tomato)
      (in pot tomato)
      (under tomato pot)
      (in pot vegetable_broth)
      (under vegetable_broth pot)
    )
    :effect (and
      (in pot tomato_soup)
      (under tomato_soup pot)
      (under stove table)
      (on table stove)
      (under olive_oil pot)
      (under onion pot)
      (is-chopped tomato)
      (under tomato pot)
      (under vegetable_broth pot)
      (on stove pot)
      (under pot stove)
    )
  )

  (:action scoop_bowl_61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under tomato_soup pot)
      (under ladle table)
      (on table ladle)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl tomato_soup)
      (under tomato_soup bowl)
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under ladle table)
      (on table ladle)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )
)
